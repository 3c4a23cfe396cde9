#!/usr/bin/env bash
# A flight log from end to end, as a pilot would get one: qrterm in tmux flying qrsim --serve,
# start logging, calibrate, fly full control with a roll step, panic down, stop logging,
# download both logs, then plot them. Asserts the CSV files have their columns and the PNGs exist.
#
# usage: e2e_flight_log.sh QRTERM QRSIM
set -euo pipefail

qrterm=${1:?usage: e2e_flight_log.sh QRTERM QRSIM}
sim=${2:?usage: e2e_flight_log.sh QRTERM QRSIM}
root=$(cd "$(dirname "$0")/../.." && pwd)

[[ -x $qrterm && -x $sim ]] || { echo "e2e: no qrterm at $qrterm or no qrsim at $sim" >&2; exit 1; }

source "$(dirname "$0")/e2e_lib.sh"
e2e_start

e2e_pane "$qrterm" --sim "$sim" --no-joystick --log-dir "$work/logs" --params "$work/params.txt"
wait_for 'MODE +safe ' 30 "start: safe"
wait_for 'LINK up' 5 "link up"

keys 3
wait_for 'QR calibrated' 30 "calibrated"
wait_for 'MODE +safe ' 5 "back in safe"

keys s
wait_for 'log.* started|logging' 5 "logging started"

# Full control, lift to a hover, then a roll step with the arrow keys and back.
keys 5
wait_for 'MODE +full' 3 "5 enters full control"
for _ in $(seq 45); do keys a; done
sleep 2
for _ in $(seq 10); do keys Right; done
sleep 1.5
for _ in $(seq 10); do keys Left; done
sleep 1.5
keys Escape
wait_for 'MODE +panic ' 3 "ESC: panic"
wait_for 'MODE +safe ' 10 "panic settles in safe"

keys t
sleep 0.5
keys g
wait_for 'telemetry log: [0-9]+ lines ->' 90 "both logs downloaded"

exit_and_check_terminal

sensor=$work/logs/sensor_log_1.csv
telemetry=$work/logs/telemetry_log_1.csv
for f in "$sensor" "$telemetry"; do [[ -s $f ]] || fail "no $(basename "$f")"; done
head -n 1 "$sensor" | grep -q 'gyro_filtered_x_counts' || fail "sensor log header: $(head -n 1 "$sensor")"
head -n 1 "$telemetry" | grep -q 'phi_1e-4rad.*engine_front_0to1000' || fail "telemetry log header: $(head -n 1 "$telemetry")"
lines=$(($(wc -l <"$telemetry") - 1))
((lines > 300)) || fail "only $lines telemetry lines"
# The flight is in the log: full control (mode 5) with the engines running.
awk -F, 'NR > 1 && $3 == 5 && $15 > 300 { found = 1 } END { exit !found }' "$telemetry" || fail "no full-control flight in the telemetry log"

"$root/scripts/plot" "$telemetry" --out "$work/telemetry.png"
"$root/scripts/plot" "$sensor" --out "$work/sensor.png"
for png in "$work/telemetry.png" "$work/sensor.png"; do
  [[ $(head -c 4 "$png" | od -An -tx1 | tr -d ' ') == 89504e47 ]] || fail "$png is not a PNG"
done
echo "e2e: passed: $lines telemetry lines, $(($(wc -l <"$sensor") - 1)) sensor lines, both plotted"
