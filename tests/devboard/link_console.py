#!/usr/bin/env python3
"""A scripted console for the devboard: talks to the flight firmware (qr.elf) over QEMU's serial line.

It asks for manual mode and checks the ack, checks that telemetry streams, then asks the
firmware to exit and checks that it confirms and stops with status 0.
"""
import argparse
import subprocess
import sys
import time

from wire import ACK, EXIT, MODE_CHANGE, TELEMETRY_ATTITUDE, Devboard, frame, frames_in


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--elf", required=True)
    args = parser.parse_args()
    board = Devboard(args.elf, "--timeout", "40")

    def wait_for(expected, seconds):
        deadline = time.monotonic() + seconds
        while time.monotonic() < deadline:
            if expected in board.snapshot():
                return True
            time.sleep(0.01)
        return False

    def fail(what):
        board.kill()
        print(f"FAIL: {what}; last bytes received: {board.snapshot()[-64:].hex(' ')}")
        sys.exit(1)

    time.sleep(0.5)  # let the firmware start its kick
    board.send(frame(MODE_CHANGE, [1, 2]))
    if not wait_for(frame(ACK, [MODE_CHANGE, 1]), 5):
        fail("no ack for mode_change seq 1 (manual)")
    print("ack for manual mode")

    deadline = time.monotonic() + 5
    attitude = 0
    while attitude < 10 and time.monotonic() < deadline:
        attitude = sum(1 for t, _ in frames_in(board.snapshot()) if t == TELEMETRY_ATTITUDE)
        time.sleep(0.05)
    if attitude < 10:
        fail(f"telemetry does not stream ({attitude} attitude frames in 5 s)")
    print(f"telemetry streams: {attitude} attitude frames")

    board.send(frame(EXIT, [2]))
    if not wait_for(frame(ACK, [EXIT, 2]), 5):
        fail("no ack for exit seq 2")
    print("ack for exit")
    try:
        status = board.process.wait(timeout=10)  # manual -> panic (3 s) -> safe -> stopped
    except subprocess.TimeoutExpired:
        fail("firmware did not stop after exit")
    if status != 0:
        fail(f"firmware exit status {status}")
    print("firmware stopped with status 0")


if __name__ == "__main__":
    main()
