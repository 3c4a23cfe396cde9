#!/usr/bin/env python3
"""The binary you flash flies: one scenario flown by the host build and by qr.elf on the devboard
(qrsim --devboard, lock-step over the sensor link), same seed. Fails unless

  - the devboard's run says "firmware": "rv32" and reports the binary's instructions per tick;
  - both flew through the sensor drivers (the bus carried over the sensor link on the devboard);
  - every figure of the flight is within 5 % of the host's (figures of the run itself, wall time
    and speed, are not the flight's and are not compared);
  - every band has the same verdict (a known failure fails the same band with both);
  - tick for tick, wherever the firmware's inputs (its sensor samples, the bytes it received)
    were the same, its engine outputs are the same: with the lock-step both builds read the same
    samples and bytes every tick, so the engines must match on every tick of the trace.

It prints one JSON line of what it compared (scripts/test collects it among the figures).
usage: closed_loop_matches_host.py --qrsim HOST_QRSIM --elf QR_ELF --scenario NAME [--seconds S]
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys
import tempfile

NOT_FLIGHT = {"wall_seconds", "speedup", "cpu_seconds", "speedup_cpu"}


# The sensor stage's time on this host: on the devboard the stage runs on the board (its
# instructions are in instr_tick_*); the drivers' counts come over the sensor link and compare.
HOST_ONLY = {"sensor_stage_ns_mean"}


def fly(qrsim, scenario, trace, seconds, elf=None):
    # Both through the sensor drivers (the default): on the devboard the sensor link carries the
    # I2C bus to the simulator's chip models (docs/devboard.md, "The sensor link").
    cmd = [qrsim, "--scenario", scenario, "--json", "--trace", trace]
    cmd += ["--devboard", elf] if elf else []
    cmd += ["--seconds", str(seconds)] if seconds else []
    run = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
    if run.returncode not in (0, 1):
        sys.exit(f"{' '.join(cmd)} failed ({run.returncode}): {run.stderr}")
    return json.loads(run.stdout)


def close(a, b):
    if a is None or b is None:
        return a is None and b is None
    if isinstance(a, str) or isinstance(b, str):
        return a == b
    if a == b:
        return True
    return abs(a - b) <= 0.05 * max(abs(a), abs(b))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--qrsim", required=True)
    parser.add_argument("--elf", required=True)
    parser.add_argument("--scenario", required=True)
    parser.add_argument("--seconds", type=float, help="the scenario's scored time (default its own)")
    args = parser.parse_args()
    for path in (args.qrsim, args.elf):
        if not os.path.exists(path):
            sys.exit(f"missing {path}: build the host and rv32 presets first (scripts/test does)")

    with tempfile.TemporaryDirectory() as work:
        host_trace, board_trace = os.path.join(work, "host.csv"), os.path.join(work, "rv32.csv")
        host = fly(args.qrsim, args.scenario, host_trace, args.seconds)
        board = fly(args.qrsim, args.scenario, board_trace, args.seconds, args.elf)
        problems = []
        if board.get("firmware") != "rv32":
            problems.append(f"the devboard run says firmware {board.get('firmware')!r}")
        if not board.get("instr_tick_mean"):
            problems.append("the devboard run reports no instructions per tick")
        for name, run in (("host", host), ("devboard", board)):
            if not run.get("i2c_busy_pct"):
                problems.append(f"the {name} run did not fly through the sensor drivers (no I2C bus time)")
        if "error" in board:
            problems.append(f"the devboard run failed: {board['error']}")
        compared = 0
        for name, value in host.items():
            if name in NOT_FLIGHT | HOST_ONLY or name in ("bands", "pass", "firmware") or isinstance(value, dict):
                continue
            compared += 1
            if name not in board:
                problems.append(f"{name}: missing from the devboard run")
            elif not close(value, board[name]):
                problems.append(f"{name}: host {value}, rv32 {board[name]} (more than 5 % apart)")
        if host["bands"] != board["bands"]:
            problems.append(f"band verdicts differ: host {host['bands']}, rv32 {board['bands']}")

        with open(host_trace) as h, open(board_trace) as b:
            host_rows, board_rows = list(csv.DictReader(h)), list(csv.DictReader(b))
        engines = [f"engine{i}" for i in range(4)]
        inputs_alike = min(len(host_rows), len(board_rows))
        differing = [i for i in range(inputs_alike)
                     if [host_rows[i][e] for e in engines] != [board_rows[i][e] for e in engines]]
        if len(host_rows) != len(board_rows):
            problems.append(f"traces of {len(host_rows)} and {len(board_rows)} ticks")
        if differing:
            first = differing[0]
            problems.append(f"engines differ on {len(differing)} of {inputs_alike} ticks, first at t={host_rows[first]['t_s']} s: "
                            f"host {[host_rows[first][e] for e in engines]}, rv32 {[board_rows[first][e] for e in engines]}")

        print(json.dumps({"scenario": args.scenario, "compare": "host vs rv32 devboard", "figures_compared": compared,
                          "ticks_compared": inputs_alike, "engine_ticks_differing": len(differing),
                          "speedup_rv32": board.get("speedup"), "instr_tick_mean": board.get("instr_tick_mean"),
                          "instr_tick_max": board.get("instr_tick_max"), "pass_host": host["pass"],
                          "pass_rv32": board["pass"]}))
        for p in problems:
            print("FAIL:", p)
        return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
