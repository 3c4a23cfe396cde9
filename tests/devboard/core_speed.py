#!/usr/bin/env python3
"""A core of a given speed (docs/devboard.md): qr.elf flies a scenario at 1 kHz in lock-step with
the plant, its clock running on by its instructions at --core-mhz while a tick runs, so a tick
longer than its period is a deadline miss and its engines go out late.

Flies the scenario on a 16 MHz core, which must hold 1 kHz with no deadline miss and pass the
scenario's bands, and on a core slow enough to miss (2 MHz: a mean full-control tick of about
3,000 instructions takes 1.5 ms), which must count misses, or the model measures nothing.
Prints the figures of both flights.
usage: core_speed.py --qrsim HOST_QRSIM --elf QR_ELF [--scenario step-roll]
"""
import argparse
import json
import os
import subprocess
import sys

FAST_MHZ, SLOW_MHZ = 16, 2


def fly(args, mhz):
    run = subprocess.run([args.qrsim, "--scenario", args.scenario, "--devboard", args.elf, "--core-mhz", str(mhz),
                          "--json"], capture_output=True, text=True, timeout=600)
    lines = [line for line in run.stdout.splitlines() if line.startswith("{")]
    if not lines:
        sys.exit(f"FAIL: no figures from the {mhz} MHz flight (status {run.returncode}): {run.stderr[-500:]}")
    return run.returncode, json.loads(lines[-1])


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--qrsim", required=True)
    parser.add_argument("--elf", required=True)
    parser.add_argument("--scenario", default="step-roll")
    args = parser.parse_args()
    for path in (args.qrsim, args.elf):
        if not os.path.exists(path):
            sys.exit(f"missing {path}: build the host and rv32 presets first (scripts/test does)")

    failures = []
    for mhz in (FAST_MHZ, SLOW_MHZ):
        status, figures = fly(args, mhz)
        shown = {k: figures.get(k) for k in ("scenario", "firmware", "core_mhz", "deadline_misses", "pass",
                                              "instr_tick_mean", "instr_tick_max")}
        ticks = figures.get("instr_tick_mean")
        if ticks:
            shown["tick_us_mean"] = round(ticks / mhz, 1)
            shown["tick_us_max"] = round(figures.get("instr_tick_max", 0) / mhz, 1)
        shown["status"] = status
        print(json.dumps(shown))
        if figures.get("core_mhz") != mhz:
            failures.append(f"the {mhz} MHz flight did not run at {mhz} MHz (core_mhz {figures.get('core_mhz')})")
        misses = figures.get("deadline_misses")
        if mhz == FAST_MHZ:
            if misses != 0:
                failures.append(f"a {mhz} MHz core missed {misses} deadlines at 1 kHz")
            if status != 0:
                failures.append(f"the {mhz} MHz flight did not pass its bands (status {status})")
        elif not misses:
            failures.append(f"a {mhz} MHz core missed no deadline: the speed model measures nothing")
    for f in failures:
        print("FAIL:", f)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
