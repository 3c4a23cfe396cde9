"""The wire as a devboard test script needs it (docs/protocol.md): frames, CRC-8/DVB-S2, the
commanding requests' CRC-24 guard, a byte-stream reader, and the devboard process with a reader
thread."""
import os
import signal
import subprocess
import threading

HERE = os.path.dirname(os.path.abspath(__file__))
DEVBOARD = os.path.join(HERE, "..", "..", "scripts", "devboard")

CONTROL, MODE_CHANGE, PARAM_SET, EXIT = 0x11, 0x12, 0x14, 0x1E
ACK, NACK, TELEMETRY_ATTITUDE, TELEMETRY_SYSTEM = 0x81, 0x82, 0x88, 0x90
PAYLOAD = {0x81: 2, 0x82: 3, 0x84: 5, 0x87: 9, 0x88: 9, 0x8B: 6, 0x8D: 8, 0x8E: 8, 0x90: 8,
           0x93: 9, 0x95: 9, 0x96: 9, 0x99: 7, 0x9C: 7}
TELEMETRY_RATE_HZ = 7  # parameter id
# The requests that carry a guard (docs/protocol.md, sections 2 and 3): mode_change, param_set,
# log_start, log_stop, exit.
GUARDED = {0x12, 0x14, 0x18, 0x1B, 0x1E}


def crc8_dvb_s2(data):
    crc = 0
    for byte in data:
        crc ^= byte
        for _ in range(8):
            crc = ((crc << 1) ^ 0xD5) & 0xFF if crc & 0x80 else (crc << 1) & 0xFF
    return crc


def crc24_openpgp(data):
    crc = 0xB704CE
    for byte in data:
        crc ^= byte << 16
        for _ in range(8):
            crc = ((crc << 1) ^ 0x864CFB) & 0xFFFFFF if crc & 0x800000 else (crc << 1) & 0xFFFFFF
    return crc


def frame(msg_type, payload):
    body = bytes([msg_type]) + bytes(payload)
    if msg_type in GUARDED:
        body += crc24_openpgp(body).to_bytes(3, "little")
    return b"M" + body + bytes([crc8_dvb_s2(body)])


def control(lift, roll=0, pitch=0, yaw=0):
    return frame(CONTROL, b"".join(v.to_bytes(2, "little", signed=s)
                                   for v, s in ((lift, False), (roll, True), (pitch, True), (yaw, True))))


def frames_in(data):
    """Every frame with a good check in a QR -> PC byte stream, as (type, payload)."""
    out, i = [], 0
    while i + 2 < len(data):
        length = PAYLOAD.get(data[i + 1]) if data[i] == 0x4D else None
        if length is not None and i + 3 + length <= len(data):
            body = data[i + 1:i + 2 + length]
            if crc8_dvb_s2(body) == data[i + 2 + length]:
                out.append((body[0], bytes(body[1:])))
                i += 3 + length
                continue
        i += 1
    return out


class Devboard:
    """An ELF on the devboard with its UART on our pipes, read by a thread."""

    def __init__(self, elf, *extra):
        # A session of its own, so kill() takes QEMU down with the script that started it.
        self.process = subprocess.Popen([DEVBOARD, "--elf", elf, "--stdin", *extra],
                                        stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                        start_new_session=True)
        self.received = bytearray()
        self.lock = threading.Lock()
        threading.Thread(target=self._read, daemon=True).start()

    def _read(self):
        while True:
            chunk = self.process.stdout.read1(4096)
            if not chunk:
                return
            with self.lock:
                self.received.extend(chunk)

    def send(self, data):
        self.process.stdin.write(data)
        self.process.stdin.flush()

    def kill(self):
        try:
            os.killpg(self.process.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass

    def snapshot(self):
        with self.lock:
            return bytes(self.received)
