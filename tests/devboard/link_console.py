#!/usr/bin/env python3
"""A scripted console for the devboard: talks to the flight firmware (qr.elf) over QEMU's serial line.

It asks for manual mode and checks the ack, checks that telemetry streams, then asks the
firmware to exit and checks that it confirms and stops with status 0.
"""
import argparse
import os
import subprocess
import sys
import threading
import time

HERE = os.path.dirname(os.path.abspath(__file__))
DEVBOARD = os.path.join(HERE, "..", "..", "scripts", "devboard")


def crc8_dvb_s2(data):
    crc = 0
    for byte in data:
        crc ^= byte
        for _ in range(8):
            crc = ((crc << 1) ^ 0xD5) & 0xFF if crc & 0x80 else (crc << 1) & 0xFF
    return crc


def frame(msg_type, payload):
    body = bytes([msg_type]) + bytes(payload)
    return b"M" + body + bytes([crc8_dvb_s2(body)])


MODE_CHANGE, EXIT, ACK, TELEMETRY_ATTITUDE = 0x12, 0x1E, 0x81, 0x88


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--elf", required=True)
    args = parser.parse_args()

    qemu = subprocess.Popen([DEVBOARD, "--elf", args.elf, "--stdin", "--timeout", "40"],
                            stdin=subprocess.PIPE, stdout=subprocess.PIPE)
    received = bytearray()
    lock = threading.Lock()

    def reader():
        while True:
            chunk = qemu.stdout.read1(4096)
            if not chunk:
                return
            with lock:
                received.extend(chunk)

    threading.Thread(target=reader, daemon=True).start()

    def send(data):
        qemu.stdin.write(data)
        qemu.stdin.flush()

    def wait_for(expected, seconds):
        deadline = time.monotonic() + seconds
        while time.monotonic() < deadline:
            with lock:
                if expected in received:
                    return True
            time.sleep(0.01)
        return False

    def fail(what):
        qemu.kill()
        with lock:
            tail = bytes(received[-64:]).hex(" ")
        print(f"FAIL: {what}; last bytes received: {tail}")
        sys.exit(1)

    time.sleep(0.5)  # let the firmware start its kick
    manual = frame(MODE_CHANGE, [1, 2])
    send(manual)
    if not wait_for(frame(ACK, [MODE_CHANGE, 1]), 5):
        fail("no ack for mode_change seq 1 (manual)")
    print("ack for manual mode")

    with lock:
        attitude = received.count(bytes([0x4D, TELEMETRY_ATTITUDE]))
    if attitude == 0:
        fail("no telemetry")
    print(f"telemetry_attitude frames so far: {attitude}")

    send(frame(EXIT, [2]))
    if not wait_for(frame(ACK, [EXIT, 2]), 5):
        fail("no ack for exit seq 2")
    print("ack for exit")
    try:
        status = qemu.wait(timeout=10)  # manual -> panic (3 s) -> safe -> stopped
    except subprocess.TimeoutExpired:
        fail("firmware did not stop after exit")
    if status != 0:
        fail(f"firmware exit status {status}")
    print("firmware stopped with status 0")


if __name__ == "__main__":
    main()
