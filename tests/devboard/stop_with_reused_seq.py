#!/usr/bin/env python3
"""The stop is never answered from memory, on the devboard (docs/protocol.md section 6).

Manual is requested with seq 17 and acked; the pilot flies at lift 300; 0.5 s later panic is
requested with the same seq 17. The firmware must apply it (telemetry says panic), not ack it as a
resend of the manual request and fly on.
"""
import argparse
import subprocess
import sys
import time

from wire import ACK, EXIT, MODE_CHANGE, TELEMETRY_ATTITUDE, Devboard, control, frame, frames_in

MANUAL, PANIC = 2, 1
TELEMETRY_ENGINES = 0x8D


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--elf", required=True)
    args = parser.parse_args()
    board = Devboard(args.elf, "--timeout", "40")

    def fail(what):
        board.kill()
        print(f"FAIL: {what}; last bytes received: {board.snapshot()[-64:].hex(' ')}")
        sys.exit(1)

    def fly(seconds, lift):
        """The console's heartbeat: a control frame every 20 ms."""
        end = time.monotonic() + seconds
        while time.monotonic() < end:
            board.send(control(lift))
            time.sleep(0.02)

    def acks():
        return sum(1 for t, p in frames_in(board.snapshot()) if t == ACK and p == bytes([MODE_CHANGE, 17]))

    def last(kind, since):
        got = [p for t, p in frames_in(board.snapshot()[since:]) if t == kind]
        return got[-1] if got else None

    time.sleep(0.5)  # let the firmware start its kick
    board.send(frame(MODE_CHANGE, [17, MANUAL]))
    fly(0.3, 0)
    if acks() != 1:
        fail("no ack for mode_change seq 17 (manual)")
    fly(0.5, 300)
    mark = len(board.snapshot())
    fly(0.2, 300)
    attitude = last(TELEMETRY_ATTITUDE, mark)
    engines = last(TELEMETRY_ENGINES, mark)
    if attitude is None or attitude[1] != MANUAL or engines is None:
        fail("not flying in manual before the stop")
    engine0 = int.from_bytes(engines[0:2], "little")
    print(f"manual acked, flying: engine 0 at {engine0}")
    if engine0 == 0:
        fail("engines still at lift 300 in manual")

    board.send(frame(MODE_CHANGE, [17, PANIC]))  # the same seq, another request
    fly(0.3, 300)
    mark = len(board.snapshot())
    fly(0.2, 300)
    attitude = last(TELEMETRY_ATTITUDE, mark)
    if acks() != 2:
        fail(f"the panic request was not answered ({acks()} acks for seq 17)")
    if attitude is None or attitude[1] != PANIC:
        fail(f"panic acked but not applied: telemetry mode {attitude[1] if attitude else None}")
    print("panic with the reused seq 17: acked and applied")
    board.send(frame(EXIT, [1]))  # panic runs out (3 s), then the firmware stops
    try:
        status = board.process.wait(timeout=15)
    except subprocess.TimeoutExpired:
        fail("firmware did not stop after exit")
    if status != 0:
        fail(f"firmware exit status {status}")


if __name__ == "__main__":
    main()
