#!/usr/bin/env python3
"""Runs a firmware that commits one fault (faulty_firmware.cpp) on the devboard and checks that
the board failed safe: the engines, at flight values before, read back zero after the cut; the
report names the fault, its mcause, an address and the task; the run ends with the fault's
non-zero status, not a timeout.
"""
import argparse
import re
import subprocess
import sys

REPORT = re.compile(r"rv32virt: fail-safe: (?P<what>[a-z ()]+) mcause=(?P<mcause>0x[0-9a-f]{8}) "
                    r"mepc=(?P<mepc>0x[0-9a-f]{8}) mtval=(?P<mtval>0x[0-9a-f]{8}) task=(?P<task>\d+ \w+|none) "
                    r"engines (?P<before>\d+ \d+ \d+ \d+) -> (?P<after>\d+ \d+ \d+ \d+)")


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--devboard", required=True, help="scripts/devboard")
    parser.add_argument("--elf", required=True)
    parser.add_argument("--what", required=True, help="the fault the report must name")
    parser.add_argument("--mcause", required=True, help="its mcause, hex")
    parser.add_argument("--status", type=int, required=True, help="the exit status it must end with")
    parser.add_argument("--task", default="1 fault", help="the task the report must name")
    args = parser.parse_args()

    run = subprocess.run([args.devboard, "--elf", args.elf, "--timeout", "30"], capture_output=True, text=True)
    print(run.stdout, end="")
    print(run.stderr, end="", file=sys.stderr)
    problems = []
    m = REPORT.search(run.stdout)
    if m is None:
        problems.append("no fail-safe report line")
    else:
        if m["what"] != args.what:
            problems.append(f"fault reported as '{m['what']}', not '{args.what}'")
        if int(m["mcause"], 16) != int(args.mcause, 16):
            problems.append(f"mcause {m['mcause']}, expected {args.mcause}")
        if int(m["mepc"], 16) < 0x80000000:
            problems.append(f"mepc {m['mepc']} is not an address in the program")
        if m["task"] != args.task:
            problems.append(f"task '{m['task']}', expected '{args.task}'")
        before = [int(v) for v in m["before"].split()]
        after = [int(v) for v in m["after"].split()]
        if not all(before):
            problems.append(f"the engines were not flying before the fault ({before}): the cut proves nothing")
        if any(after):
            problems.append(f"engines after the cut {after}, not zero")
    if run.returncode != args.status:
        problems.append(f"exit status {run.returncode}, expected {args.status}")
    for p in problems:
        print("FAIL:", p)
    if not problems:
        print(f"fails safe: {m['what']}, engines {m['before']} -> {m['after']}, status {run.returncode}")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
