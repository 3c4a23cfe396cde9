#!/usr/bin/env python3
"""Checks the fixed-point bench's output (on stdin) is what its readers expect.

Every line a JSON object; one per operation with "op", "fixed_instr" and "float_instr", the
required operations all present; the last line a summary with "summary" and "iir2_ratio".
Only the shape is checked: the figures are reported, not judged here.
"""
import json
import sys

REQUIRED_OPS = {"add", "mul", "div", "sqrt", "atan2", "iir1", "iir2"}


def fail(message):
    print(f"check_bench_json: {message}", file=sys.stderr)
    sys.exit(1)


def is_number(value):
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def main():
    text = sys.stdin.read()
    sys.stdout.write(text)  # keep the figures in the test log
    lines = [line for line in text.splitlines() if line.strip()]
    if not lines:
        fail("no output")

    objects = []
    for number, line in enumerate(lines, 1):
        try:
            value = json.loads(line)
        except json.JSONDecodeError as error:
            fail(f"line {number} is not JSON ({error}): {line!r}")
        if not isinstance(value, dict):
            fail(f"line {number} is not a JSON object: {line!r}")
        objects.append(value)

    *ops, summary = objects
    seen = set()
    for value in ops:
        if "op" not in value:
            fail(f"not an operation line (no \"op\"): {value}")
        for key in ("fixed_instr", "float_instr"):
            if not is_number(value.get(key)):
                fail(f"{value['op']}: \"{key}\" missing or not a number")
        seen.add(value["op"])
    missing = REQUIRED_OPS - seen
    if missing:
        fail(f"operations missing: {sorted(missing)}")

    if not isinstance(summary.get("summary"), str):
        fail(f"last line has no \"summary\" string: {summary}")
    if not is_number(summary.get("iir2_ratio")):
        fail(f"last line has no numeric \"iir2_ratio\": {summary}")


if __name__ == "__main__":
    main()
