#!/usr/bin/env bash
# Recordings from before the barometer on the devboard against the host: a replay CSV without the
# pressure_pa column, and a version 1 devboard recording (24-byte records, no pressure), must both
# replay to the host's CSV for the same input, byte for byte (no barometer: height columns 0).
# usage: replay_without_pressure.sh HOST_QRREPLAY IN.csv REPLAY_ELF
set -euo pipefail
host_replay=$1 input=$2 replay_elf=$3
root=$(cd "$(dirname "$0")/../.." && pwd)
[[ -x $host_replay ]] || { echo "no host replay at $host_replay: build the host preset first (scripts/test does)"; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
sed 's/,[^,]*$//' "$input" >"$work/old.csv"
head -n 1 "$work/old.csv" | grep -qx 'time_us,gyro_x,gyro_y,gyro_z,accel_x,accel_y,accel_z,battery_mv,lift,roll,pitch,yaw'
"$(dirname "$0")/replay_matches_host.sh" "$host_replay" "$work/old.csv" "$replay_elf"
"$host_replay" --replay "$work/old.csv" --out "$work/host.csv" 2>"$work/host.err"
grep -q "the barometer is absent" "$work/host.err"
python3 - "$work/old.csv" "$work/v1.rec" <<'PY'
import struct, sys
rows = [[int(x) for x in line.split(",")] for line in open(sys.argv[1]).read().splitlines()[1:]]
step = rows[1][0] - rows[0][0]
out = bytearray(b"QRRC" + struct.pack("<HHIII", 1, 24, len(rows), 1000000 // step, rows[0][0]))
for v in rows:
    out += struct.pack("<hhhhhhHHhhhH", *v[1:12], 0)
open(sys.argv[2], "wb").write(out)
PY
"$root/scripts/devboard" --elf "$replay_elf" --recording "$work/v1.rec" --timeout 120 >"$work/devboard.csv"
cmp "$work/devboard.csv" "$work/host.csv"
echo "version 1 recording: $(($(wc -l <"$work/host.csv") - 1)) ticks, identical on the devboard and the host"
