#!/usr/bin/env python3
"""The console's path to the binary in the simulator (scripts/run --devboard): qrsim --serve
--stdio --devboard runs qr.elf in real time in lock-step with the plant, and a scripted console on
qrsim's line asks for manual mode, sees the ack and telemetry, asks for exit, and sees qrsim end
with status 0 once the firmware has stopped. On the truth channel (--truth-fd) qrsim says once a
second what the devboard's tick costs in RV32 instructions, with no core clock (the console's CPU
row and b key, docs/console.md).
usage: served_devboard_console.py --qrsim HOST_QRSIM --elf QR_ELF
"""
import argparse
import os
import subprocess
import sys
import threading
import time

from wire import ACK, EXIT, MODE_CHANGE, TELEMETRY_ATTITUDE, control, frame, frames_in


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--qrsim", required=True)
    parser.add_argument("--elf", required=True)
    args = parser.parse_args()
    for path in (args.qrsim, args.elf):
        if not os.path.exists(path):
            sys.exit(f"missing {path}: build the host and rv32 presets first (scripts/test does)")
    truth_read, truth_write = os.pipe()
    sim = subprocess.Popen([args.qrsim, "--serve", "--stdio", "--devboard", args.elf, "--seconds", "30",
                            "--truth-fd", str(truth_write)],
                           stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                           pass_fds=(truth_write,))
    os.close(truth_write)
    received = bytearray()
    devboard_lines = []
    lock = threading.Lock()

    def read_truth():
        with os.fdopen(truth_read, "r") as truth:
            for line in truth:
                if line.startswith("devboard "):
                    with lock:
                        devboard_lines.append(line.strip())

    threading.Thread(target=read_truth, daemon=True).start()

    def read():
        while True:
            chunk = sim.stdout.read1(4096)
            if not chunk:
                return
            with lock:
                received.extend(chunk)

    threading.Thread(target=read, daemon=True).start()

    def frames():
        with lock:
            return frames_in(bytes(received))

    def send(data):
        sim.stdin.write(data)
        sim.stdin.flush()

    def fail(what):
        sim.kill()
        print(f"FAIL: {what}; qrsim said: {sim.stderr.read().decode(errors='replace')[-500:]}")
        sys.exit(1)

    def wait_for(check, seconds):
        deadline = time.monotonic() + seconds
        while time.monotonic() < deadline:
            send(control(0))  # the console's heartbeat, neutral sticks
            if check():
                return True
            time.sleep(0.02)
        return False

    send(frame(MODE_CHANGE, [1, 2]))
    if not wait_for(lambda: (ACK, bytes([MODE_CHANGE, 1])) in frames(), 10):
        fail("no ack for mode_change seq 1 (manual)")
    if not wait_for(lambda: any(t == TELEMETRY_ATTITUDE and p[1] == 2 for t, p in frames()), 5):
        fail("no telemetry showing manual mode")
    attitude = sum(1 for t, _ in frames() if t == TELEMETRY_ATTITUDE)
    if not wait_for(lambda: len(devboard_lines) > 0, 5):
        fail("no devboard line on the truth channel")
    fields = dict(item.split("=") for item in devboard_lines[0].split()[1:])
    mean, largest, ticks = float(fields["tick_instr_mean"]), int(fields["tick_instr_max"]), int(fields["ticks"])
    if fields["core_mhz"] != "0" or not 0 < mean <= largest or ticks < 400:
        fail(f"the devboard line's figures: {devboard_lines[0]}")
    send(frame(EXIT, [2]))
    try:
        status = sim.wait(timeout=10)
    except subprocess.TimeoutExpired:
        fail("qrsim did not end after the exit request")
    if status != 0:
        fail(f"qrsim ended with status {status}")
    print(f"served devboard: ack for manual, {attitude} attitude frames, exit carried out, qrsim status 0; "
          f"on the truth channel: {devboard_lines[0]}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
