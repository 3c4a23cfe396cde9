#!/usr/bin/env bash
# Settings that do not trap (issue 36), in tmux against the fake QR: a parameter file with
# pilot = 1, saved from a session with the simulator's radio, and a plain start without one. The
# console names the value, why it cannot work here and the fix before anything is flown; set back
# on the parameter screen, the exit names the undo.
# usage: e2e_settings_trap.sh QRTERM FAKE_QR
set -euo pipefail

qrterm=${1:?usage: e2e_settings_trap.sh QRTERM FAKE_QR}
sim=${2:?usage: e2e_settings_trap.sh QRTERM FAKE_QR}
[[ -x $qrterm && -x $sim ]] || { echo "e2e: no qrterm at $qrterm or no fake QR at $sim" >&2; exit 1; }

source "$(dirname "$0")/e2e_lib.sh"
e2e_start

export LC_ALL=C
echo "pilot = 1" >"$work/params.txt"
e2e_pane "$qrterm" --sim "$sim" --no-joystick --log-dir "$work/logs" --params "$work/params.txt"
wait_for 'pilot = 1 \(the radio flies\) but this simulator has no radio' 5 "the saved radio pilot named at start"
grep -q 'Set pilot 0 on the parameter screen (Tab Tab, select pilot, =), or start with a radio (scripts/run --radio)' \
  "$work/logs/console.log" || fail "the warning lacks its fix"
wait_for 'LINK up' 5 "link up"

# The fix as the warning says it: on the parameter screen, pilot, =.
keys Tab Tab
wait_for 'PARAMETERS' 3 "the parameter screen"
for _ in $(seq 27); do keys Down; done
wait_for 'pilot \[0 PC link, 1 radio\]' 3 "pilot selected"
keys =
wait_for '^pilot +0 +read back' 5 "pilot back to 0, read back"
keys x
wait_for 'QRTERM ENDED' 5 "x exits"
wait_for 'pilot 1 -> 0 +undo: pilot = 1' 1 "the exit names the change and its undo"
grep -qx 'pilot = 0' "$work/params.txt" || fail "the parameter file still has the radio as the pilot"
echo "e2e: passed"
