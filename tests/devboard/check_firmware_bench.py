#!/usr/bin/env python3
"""Reads the firmware bench's output on stdin: every line a JSON object, one per mode with its
figures, the summary last. Fails on malformed output or a mode that could not be armed, never on
the figures themselves (they are reported, not asserted)."""
import json
import sys

MODES = ["safe", "panic", "manual", "calibration", "yaw", "full", "full-float"]


def main():
    lines = [line for line in sys.stdin.read().splitlines() if line.strip()]
    for line in lines:
        print(line)
    try:
        objects = [json.loads(line) for line in lines]
    except json.JSONDecodeError as e:
        sys.exit(f"malformed JSON line: {e}")
    if not objects or any(k not in objects[-1] for k in ("summary", "full_tick_instr_mean", "float_over_fixed")):
        sys.exit("the last line must be the summary with full_tick_instr_mean and float_over_fixed")
    seen = {o.get("mode"): o for o in objects[:-1]}
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


if __name__ == "__main__":
    main()
