#!/usr/bin/env bash
# The simulator killed mid-flight, through the real program in tmux: in manual with the engines
# running, the simulator dies; the screen says LINK LOST, why, and that the QR panics by itself;
# the abort key still answers (and says nothing can be sent); x exits and the terminal is given
# back; the session's files are there.
#
# usage: e2e_sim_killed_in_flight.sh QRTERM SIMULATOR   (the fake QR or qrsim, as e2e_console.sh)
set -euo pipefail

qrterm=${1:?usage: e2e_sim_killed_in_flight.sh QRTERM SIMULATOR}
sim=${2:?usage: e2e_sim_killed_in_flight.sh QRTERM SIMULATOR}

[[ -x $qrterm ]] || { echo "e2e: no qrterm at $qrterm" >&2; exit 1; }
[[ -x $sim ]] || { echo "e2e: no simulator at $sim" >&2; exit 1; }

source "$(dirname "$0")/e2e_lib.sh"
e2e_start

e2e_pane "$qrterm" --sim "$sim" --no-joystick --log-dir "$work/logs" --params "$work/params.txt"
wait_for 'MODE +safe ' 30 "start: the screen shows safe"
wait_for 'LINK up' 5 "link up"
find_sim_pid

# Flying: manual, lift raised.
keys 2
wait_for 'MODE +manual ' 3 "2 enters manual"
for _ in $(seq 10); do keys a; done
wait_for 'sending +lift +100 ' 3 "lift 100"

# The simulator dies in flight.
kill -KILL "$sim_pid"
wait_for 'LINK LOST' 2 "simulator killed: LINK LOST"
wait_for 'it panics by itself' 2 "the screen says what the QR does on its own"

# The abort key still answers, and does not pretend.
keys Escape
wait_for 'nothing can be sent' 2 "ESC after the line is gone"

exit_and_check_terminal
[[ -s $work/logs/telemetry.csv ]] || fail "no telemetry.csv in the log folder"
echo "e2e: passed"
