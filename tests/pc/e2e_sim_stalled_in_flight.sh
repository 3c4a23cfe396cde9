#!/usr/bin/env bash
# The simulator stalled mid-flight, flown by hand through the real program in tmux (issue 30): in
# full control with the vehicle off the ground, qrsim is stopped for 2 s (SIGSTOP, as a loaded
# host or a debugger stops it) and goes on. The world pauses rather than skipping 2 s, so the QR
# sees no gap in the console's frames: no panic, full control after it; the console's log says
# the simulator stalled (qrsim's stderr line; the console's own LINK LOST for the 2 s it heard
# nothing is its wall clock's, and right). Then ESC and x, as a pilot ends.
#
# usage: e2e_sim_stalled_in_flight.sh QRTERM QRSIM
set -euo pipefail

qrterm=${1:?usage: e2e_sim_stalled_in_flight.sh QRTERM QRSIM}
sim=${2:?usage: e2e_sim_stalled_in_flight.sh QRTERM QRSIM}

[[ -x $qrterm ]] || { echo "e2e: no qrterm at $qrterm" >&2; exit 1; }
[[ -x $sim ]] || { echo "e2e: no simulator at $sim" >&2; exit 1; }

source "$(dirname "$0")/e2e_lib.sh"
e2e_start

height() { screen | sed -nE 's/.*truth roll [-+][0-9.]+ pitch [-+][0-9.]+ yaw [-+][0-9.]+ height ([0-9.]+) m.*/\1/p'; }

e2e_pane "$qrterm" --sim "$sim" --no-joystick --log-dir "$work/logs" --params "$work/params.txt"
wait_for 'MODE +safe ' 30 "start: the screen shows safe"
wait_for 'LINK up' 5 "link up"
find_sim_pid

keys 3
wait_for 'QR calibrated' 30 "calibration done"
wait_for 'MODE +safe ' 5 "back in safe after calibration"
keys 5
wait_for 'MODE +full ' 3 "5 enters full control"
# Off the ground: lift 600 climbs (the hover is about 530).
for _ in $(seq 60); do keys a; done
wait_for 'sending +lift +600 ' 3 "lift 600"
deadline=$((SECONDS + 8))
until awk -v h="$(height)" 'BEGIN { exit !(h + 0 > 0.3) }'; do
  ((SECONDS <= deadline)) || fail "the vehicle did not leave the ground (truth height $(height))"
  sleep 0.1
done
echo "e2e: ok: flying, truth height $(height) m"

kill -STOP "$sim_pid"
sleep 2
kill -CONT "$sim_pid"
wait_for 'sim: qrsim: the host stalled for [0-9.]+ s' 3 "the console's log says the simulator stalled"
sleep 1.5
screen | grep -Eq 'MODE +full ' || fail "not in full control 1.5 s after the stall"
if grep -q 'panic' "$work/logs/console.log"; then fail "a panic after the stall"; fi
echo "e2e: ok: full control, no panic, 1.5 s after the stall; $(grep -o 'the host stalled for [0-9.]* s' "$work/logs/console.log")"

keys Escape
wait_for 'MODE +panic ' 3 "ESC: panic"
exit_and_check_terminal
echo "e2e: passed"
