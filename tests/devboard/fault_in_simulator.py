#!/usr/bin/env python3
"""A firmware that fails (faulty_firmware.cpp) flown in lock-step by qrsim --devboard: the plant's
engines, which were at flight values, end at zero within a tick of the fault (the board's cut
answers the kick with zero engines on the sensor link), and the run ends at once rather than
waiting for an answer that never comes.
"""
import argparse
import json
import subprocess
import sys


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--qrsim", required=True)
    parser.add_argument("--elf", required=True)
    args = parser.parse_args()
    run = subprocess.run([args.qrsim, "--scenario", "hover", "--devboard", args.elf, "--json"],
                         capture_output=True, text=True, timeout=120)
    print(run.stdout, end="")
    print(run.stderr, end="", file=sys.stderr)
    figures = json.loads(run.stdout.strip().splitlines()[-1])
    problems = []
    # The fault is on tick 20 of the firmware (faulty_firmware.cpp): the flight ends there.
    if figures["sim_seconds"] > 0.1:
        problems.append(f"the flight went on for {figures['sim_seconds']} s after the fault")
    if figures["engines_at_end_max"] != 0:
        problems.append(f"the plant's engines ended at {figures['engines_at_end_max']}, not zero")
    # qrsim may say the devboard went away (its UART or link closed): it did, halted by the fault.
    for p in problems:
        print("FAIL:", p)
    if not problems:
        print(f"fails safe in the simulator: ended at {figures['sim_seconds']} s, engines 0"
              f" (qrsim: {figures.get('error') or 'the firmware stopped'})")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
