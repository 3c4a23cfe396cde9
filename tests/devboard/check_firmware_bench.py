#!/usr/bin/env python3
"""Reads the firmware bench's output on stdin: every line a JSON object, one per mode with its
figures, the drivers, the sensor stage and the scheduler lines, the summary last. Fails on
malformed output, a mode that could not be armed or a sensor stage that did not stream. The
figures themselves are reported, not asserted, with one exception: with --budgets, it fails when
a task's largest run in a fixed-point mode took more instructions than its budget (the task
table's, qr/core/flight_tasks.hpp): the budgets are the contract a student changes deliberately.
The float chain's modes are a speed comparison and have no budgets."""
import argparse
import json
import sys

MODES = ["safe", "panic", "panic-landing", "manual", "calibration", "yaw", "full", "full-float", "full-radio-dshot",
         "full-log-1khz"]


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--budgets", action="store_true", help="also fail on a task over its budget")
    args = parser.parse_args()
    lines = [line for line in sys.stdin.read().splitlines() if line.strip()]
    for line in lines:
        print(line)
    try:
        objects = [json.loads(line) for line in lines]
    except json.JSONDecodeError as e:
        sys.exit(f"malformed JSON line: {e}")
    if not objects or any(k not in objects[-1] for k in ("summary", "full_tick_instr_mean", "float_over_fixed")):
        sys.exit("the last line must be the summary with full_tick_instr_mean and float_over_fixed")
    seen = {o.get("mode"): o for o in objects[:-1] if "mode" in o}
    drivers = [o for o in objects[:-1] if "drivers" in o]
    if len(drivers) != 1 or any(drivers[0].get(k, 0) <= 0 for k in ("dshot4_instr_mean", "crsf_rc_instr_mean")):
        sys.exit("no drivers line with dshot4_instr_mean and crsf_rc_instr_mean")
    stages = [o for o in objects[:-1] if "sensor_stage" in o]
    if len(stages) != 1 or any(stages[0].get(k, 0) <= 0 for k in ("instr_mean", "bus_us_per_tick_mean", "imu_samples")):
        sys.exit("no sensor_stage line with instr_mean, bus_us_per_tick_mean and imu_samples")
    if stages[0].get("faults", 1) != 0 or stages[0]["imu_samples"] != stages[0].get("ticks"):
        sys.exit(f"the sensor stage did not stream a sample a tick without faults: {stages[0]}")
    floors = [o for o in objects[:-1] if "scheduler" in o]
    if len(floors) != 1 or any(floors[0].get(k, 0) <= 0 for k in ("bare_tick_instr_mean", "row_instr_mean")):
        sys.exit("no scheduler line with bare_tick_instr_mean and row_instr_mean")
    for mode in MODES:
        o = seen.get(mode)
        if o is None:
            sys.exit(f"no line for mode {mode}")
        if "error" in o:
            sys.exit(f"mode {mode}: {o['error']}")
        for key in ("ticks", "tick_instr_mean", "tick_instr_max", "tasks"):
            if key not in o:
                sys.exit(f"mode {mode}: no {key}")
        if o["ticks"] == 0 or not o["tasks"]:
            sys.exit(f"mode {mode}: nothing measured")
        for name, task in o["tasks"].items():
            for key in ("runs", "mean", "max", "budget", "overruns"):
                if key not in task:
                    sys.exit(f"mode {mode}, task {name}: no {key}")
    if args.budgets:
        over = [f"{mode}/{name}: max {t['max']} > budget {t['budget']} ({t['overruns']} overruns)"
                for mode, o in seen.items() if mode in MODES and not mode.endswith("-float")
                for name, t in o["tasks"].items() if t["max"] > t["budget"]]
        if over:
            sys.exit("tasks over their budgets: " + "; ".join(over))
        print("every task within its budget in every fixed-point mode")


if __name__ == "__main__":
    main()
