#!/usr/bin/env python3
"""The flight firmware on a 16 MHz-class virtual core (QEMU -icount shift=6: 64 ns per
instruction) for a sustained run in full control: telemetry at 100 Hz, control frames at 50 Hz,
in real time. Prints one JSON object with the deadline misses and load the firmware reported.

The figures are reported, not asserted; the run fails only if the firmware stops answering.
"""
import argparse
import json
import struct
import subprocess
import sys
import threading
import time

from wire import (ACK, EXIT, MODE_CHANGE, PARAM_SET, TELEMETRY_ATTITUDE, TELEMETRY_RATE_HZ,
                  TELEMETRY_SYSTEM, Devboard, control, frame, frames_in)


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--elf", required=True)
    parser.add_argument("--seconds", type=float, default=60)
    args = parser.parse_args()
    board = Devboard(args.elf, "--icount-shift", "6", "--timeout", str(int(args.seconds) + 60))

    sticks = {"lift": 0}
    stop = threading.Event()

    def heartbeat():  # control frames at 50 Hz, the console's pace
        next_at = time.monotonic()
        while not stop.is_set():
            board.send(control(sticks["lift"]))
            next_at += 0.02
            time.sleep(max(0.0, next_at - time.monotonic()))

    def fail(what):
        stop.set()
        board.kill()
        print(f"FAIL: {what}")
        sys.exit(1)

    def request(seq, payload_type, payload, seconds=3):
        board.send(frame(payload_type, payload))
        deadline = time.monotonic() + seconds
        while time.monotonic() < deadline:
            if frame(ACK, [payload_type, seq]) in board.snapshot():
                return
            time.sleep(0.01)
        fail(f"no ack for request type 0x{payload_type:02X} seq {seq}")

    def wait_for_attitude(condition, seconds, after=0):
        """Waits for a telemetry_attitude frame (sent after byte `after`) that meets condition."""
        deadline = time.monotonic() + seconds
        while time.monotonic() < deadline:
            if any(condition(p) for t, p in frames_in(board.snapshot()[after:]) if t == TELEMETRY_ATTITUDE):
                return True
            time.sleep(0.05)
        return False

    time.sleep(0.5)
    threading.Thread(target=heartbeat, daemon=True).start()
    request(1, PARAM_SET, bytes([1, TELEMETRY_RATE_HZ]) + struct.pack("<i", 100))
    mark = len(board.snapshot())
    request(2, MODE_CHANGE, [2, 3])  # calibration; it returns to safe when done
    # Timed by the firmware's own telemetry, not the wall clock: a loaded host runs QEMU slower.
    if not wait_for_attitude(lambda p: p[1] == 0 and p[2] & 0x01, 30, mark):
        fail("calibration did not finish")
    request(3, MODE_CHANGE, [3, 5])  # full control
    sticks["lift"] = 400

    start = len(board.snapshot())
    t0 = time.monotonic()
    time.sleep(args.seconds)
    window = board.snapshot()[start:]
    elapsed = time.monotonic() - t0
    frames = frames_in(window)
    modes = [p[1] for t, p in frames if t == TELEMETRY_ATTITUDE]
    systems = [struct.unpack("<HHHH", p) for t, p in frames if t == TELEMETRY_SYSTEM]
    if not systems:
        fail("no telemetry_system during the run")

    stop.set()
    board.send(frame(EXIT, [4]))
    try:
        board.process.wait(timeout=15)
    except subprocess.TimeoutExpired:
        fail("firmware did not stop after exit")

    first, last = systems[0], systems[-1]
    print(json.dumps({
        "seconds": round(elapsed, 1),
        "icount_shift": 6,
        "control_hz_sent": 50,
        "telemetry_attitude_hz": round(len(modes) / elapsed, 1),
        "final_mode_during_run": modes[-1] if modes else None,
        "deadline_misses": (last[3] - first[3]) & 0xFFFF,
        "deadline_misses_since_start": last[3],
        "cpu_load_permille_max": max(s[1] for s in systems),
        "loop_time_us_max": max(s[2] for s in systems),
    }))
    if modes and modes[-1] != 5:
        # Say why: a fail-safe report (the board halted), or the mode telemetry last showed.
        text = board.snapshot().decode("latin-1")
        report = text[text.find("rv32virt: fail-safe"):].split("\n")[0] if "rv32virt: fail-safe" in text else None
        fail(f"the firmware left full control during the run (last mode {modes[-1]}, "
             f"{report or 'no fail-safe report'})")


if __name__ == "__main__":
    main()
