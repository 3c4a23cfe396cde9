#!/usr/bin/env bash
# qrterm --joystick-wizard through the real program, in tmux, on a FIFO of struct js_event records
# standing in for /dev/input/js0. The stick under test is laid out unlike the default map: roll on
# axis 1 (resting off centre at +983), pitch on axis 0 reading pulled-back as negative, yaw on axis 3,
# the throttle on axis 2 idle at +32767, fire on button 2. The pilot's steps are fed as events, the
# map file written is checked line by line, then qrterm flies the fake QR with it.
#
# usage: e2e_joystick_wizard.sh QRTERM FAKE_QR
set -euo pipefail

qrterm=${1:?usage: e2e_joystick_wizard.sh QRTERM FAKE_QR}
fake_qr=${2:?usage: e2e_joystick_wizard.sh QRTERM FAKE_QR}

source "$(dirname "$0")/e2e_lib.sh"
e2e_start

fifo=$work/js0
map=$work/joystick.txt
mkfifo "$fifo"

axis() { for value in "${@:2}"; do js_event $AXIS "$1" "$value"; done; }
plugged_in() {
  js_event $((AXIS | INIT)) 0 0
  js_event $((AXIS | INIT)) 1 983
  js_event $((AXIS | INIT)) 2 32767
  js_event $((AXIS | INIT)) 3 0
  for button in 0 1 2 3; do js_event $((BUTTON | INIT)) "$button" 0; done
}

exec 7<>"$fifo"  # read-write: the FIFO does not wait for a reader, and what is written waits for qrterm
plugged_in
e2e_pane "$qrterm" --joystick-wizard --joystick "$fifo" --joystick-map "$map"
wait_for 'Step 1 of 6: rest' 10 "the wizard starts at the rest"
wait_for 'axes now: +0 \+0 +1 \+983 +2 \+32767 +3 \+0' 2 "the axes as plugged in"
keys Enter
wait_for 'Step 2 of 6: roll' 3 "a second of rest, then roll"

axis 1 32767 -32767 983
wait_for 'found: axis 1, moved -32767\.\.32767, reads \+$' 2 "roll: axis 1"
keys Enter
wait_for 'Step 3 of 6: pitch' 2 "pitch"
axis 0 -32767 32767 0
wait_for 'found: axis 0, moved -32767\.\.32767, reads - \(inverted\)' 2 "pitch: axis 0, back reads negative"
keys Enter
wait_for 'Step 4 of 6: yaw' 2 "yaw"
axis 3 32767 -32767 0
wait_for 'found: axis 3, ' 2 "yaw: axis 3"
keys Enter
wait_for 'Step 5 of 6: lift' 2 "lift"
axis 2 0 -32767 32767
wait_for 'found: axis 2, moved -32767\.\.32767, reads - \(inverted\)' 2 "lift: axis 2, idle at +32767"
keys Enter
wait_for 'Step 6 of 6: fire' 2 "fire"
js_event $BUTTON 2 1
js_event $BUTTON 2 0
wait_for 'deadband 60 per mille' 2 "review: the deadband"
wait_for '^ +twice the 30 per mille roll read at rest' 1 "from roll resting at +983"
wait_for 'Enter: write ' 1 "nothing refused"
keys Enter
wait_for 'QRTERM ENDED' 3 "Enter writes the map and leaves"
[[ $(cat "$work/status") == 0 ]] || fail "the wizard ended with status $(cat "$work/status")"
cmp -s "$work/stty.before" "$work/stty.after" || fail "terminal settings not restored"
screen | grep -q "joystick map written to $map" || fail "no word of the map written"
expected=(
  "lift_axis = 2" "lift_invert = yes" "roll_axis = 1" "roll_invert = no" "pitch_axis = 0" "pitch_invert = yes"
  "yaw_axis = 3" "yaw_invert = no" "abort_button = 2" "deadband = 60"
)
for line in "${expected[@]}"; do
  grep -qx "$line" "$map" || { cat "$map" >&2; fail "the map has no line \"$line\""; }
done
echo "e2e: ok: the map file"

# Flown with it: neutral with roll resting at +983, the throttle's lift past the band of 60,
# pulled back is nose up, the fire button aborts.
"${tmux[@]}" kill-session -t e2e
plugged_in
e2e_pane "$qrterm" --sim "$fake_qr" --joystick "$fifo" --joystick-map "$map" --log-dir "$work/logs" \
  --params "$work/params.txt"
wait_for 'MODE +safe ' 30 "qrterm starts with the map"
wait_for "joystick .*js0 neutral" 2 "neutral: roll at rest inside the band"
keys 2
wait_for 'MODE +manual ' 3 "manual"
axis 2 0
axis 0 -32767
wait_for 'sending +lift +468 +roll +\+0 +pitch +\+1000 ' 2 "half throttle is lift 468, pulled back is pitch +1000"
js_event $BUTTON 2 1
js_event $BUTTON 2 0
wait_for 'ABORT \(joystick fire button\)' 2 "button 2 aborts"
exit_and_check_terminal
echo "e2e: passed"
