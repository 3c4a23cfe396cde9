#!/usr/bin/env bash
# The parameter screen in tmux (issue 17), against the fake QR: every parameter listed with its
# range and default; roll_pitch_p1 typed in, seen pending or at once read back from the QR, no file
# value beside it before there is a file; a step with the arrow key; saved to a named file, whose
# value is then beside it, and loaded back.
set -euo pipefail

qrterm=${1:?usage: e2e_parameters.sh QRTERM FAKE_QR}
sim=${2:?usage: e2e_parameters.sh QRTERM FAKE_QR}
[[ -x $qrterm && -x $sim ]] || { echo "e2e: no qrterm at $qrterm or no fake QR at $sim" >&2; exit 1; }

source "$(dirname "$0")/e2e_lib.sh"
e2e_start

export LC_ALL=C
e2e_pane "$qrterm" --sim "$sim" --no-joystick --log-dir "$work/logs" --params "$work/params.txt"
wait_for 'MODE +safe ' 30 "start: safe"
wait_for 'LINK up' 5 "link up"

keys Tab Tab
wait_for 'PARAMETERS' 3 "Tab Tab: the parameter screen"
wait_for '^yaw_p +300 +read back +0\.\.1000 +300 *$' 10 "yaw_p: value, read back, range, default"
wait_for 'yaw_p \[thrust units per rad/s\]: yaw rate controller gain' 1 "the selected row's unit and meaning"

keys Down
keys Enter
keys -l 6.5
keys Enter
# No parameter file yet (it is written at exit): nothing in the file column.
wait_for '^roll_pitch_p1 +6\.5 +read back +0\.\.20 +5\.5 *$' 5 "P1 typed: read back from the QR, no file value beside it"
grep -q 'roll_pitch_p1 = 6.5' "$work/logs/console.log" || fail "the change is not in the log"

keys Right
wait_for '^roll_pitch_p1 +6\.75 +read back' 5 "right: one step up (0.25), read back"

keys Enter
keys -l 99
keys Enter
wait_for 'roll_pitch_p1 = 99 is outside 0 \.\. 20' 3 "a value out of range is refused with the range"

keys C-s
wait_for 'save parameters to file:' 3 "^S asks for a file name"
for _ in $(seq 40); do keys BSpace; done
keys -l "$work/flight-a.txt"
keys Enter
wait_for 'parameters saved to' 3 "saved"
grep -q '^roll_pitch_p1 = 6.75$' "$work/flight-a.txt" || fail "the saved file lacks roll_pitch_p1 = 6.75"
wait_for '^roll_pitch_p1 +6\.75 +read back +0\.\.20 +5\.5 *$' 3 "after the save the file's value is the screen's"

keys Left Left Left
wait_for '^roll_pitch_p1 +6 +read back +0\.\.20 +5\.5 +6\.75 *$' 5 "three steps down: the saved file's 6.75 beside it"
keys C-o
keys -l "$work/flight-a.txt"
keys Enter
wait_for 'parameters loaded from' 3 "loaded"
wait_for '^roll_pitch_p1 +6\.75 +read back' 5 "the file's value sent and read back"

keys Escape
wait_for 'ABORT' 3 "ESC still aborts on the parameter screen"
exit_and_check_terminal
echo "e2e: passed"
