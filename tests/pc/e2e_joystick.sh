#!/usr/bin/env bash
# qrterm's joystick path through the real program, in tmux: a FIFO stands in for /dev/input/js0
# and this script writes struct js_event records into it as the driver would.
#   neutral at start; throttle open -> flight refused with the reason; throttle closed -> manual;
#   throttle open -> lift; fire -> abort; the joystick gone in flight -> panic; back -> usable.
#
# usage: e2e_joystick.sh QRTERM SIMULATOR   (SIMULATOR as for e2e_console.sh)
set -euo pipefail

qrterm=${1:?usage: e2e_joystick.sh QRTERM SIMULATOR}
sim=${2:?usage: e2e_joystick.sh QRTERM SIMULATOR}

source "$(dirname "$0")/e2e_lib.sh"
e2e_start

fifo=$work/js0
mkfifo "$fifo"

throttle() { js_event $AXIS 3 "$1"; }  # the default map: axis 3, inverted (+32767 closed)
initial_state() {
  for axis in 0 1 2; do js_event $((AXIS | INIT)) "$axis" 0; done
  js_event $((AXIS | INIT)) 3 32767
  js_event $((BUTTON | INIT)) 0 0
}

# Opened read-write, the FIFO does not wait for a reader; what is written waits in it for qrterm.
exec 7<>"$fifo"
initial_state

e2e_pane "$qrterm" --sim "$sim" --joystick "$fifo" --joystick-map "$work/none" --log-dir "$work/logs" --params "$work/params.txt"
wait_for 'MODE +safe ' 30 "start"
wait_for "joystick .*js0 neutral" 2 "the joystick is neutral at start"

throttle 0
wait_for 'js +473 ' 2 "throttle half open: lift 473 (past the 5 % deadband)"
keys 2
wait_for 'not asking for manual: joystick throttle not at zero' 2 "flight refused with the throttle open"

throttle 32767
wait_for 'joystick neutral' 2 "throttle closed"
keys 2
wait_for 'MODE +manual ' 3 "manual with the joystick neutral"
throttle 0
wait_for 'sending +lift +473 ' 2 "the throttle is the lift"

js_event $BUTTON 0 1
js_event $BUTTON 0 0
wait_for 'ABORT \(joystick fire button\)' 2 "fire aborts"
wait_for 'MODE +panic ' 2 "panic"
throttle 32767
wait_for 'MODE +safe ' 10 "panic settles in safe"

keys 2
wait_for 'MODE +manual ' 3 "manual again"
exec 7>&-  # the last writer goes: the reader sees the end of the stream, as of an unplugged device
wait_for 'ABORT \(joystick lost\)' 2 "the joystick gone in flight: abort"
wait_for 'joystick LOST' 1 "LOST on the screen"
wait_for 'MODE +panic ' 2 "panic"

exec 7<>"$fifo"
initial_state
wait_for 'joystick back' 3 "the joystick is back"
wait_for 'joystick neutral' 2 "and neutral"

exit_and_check_terminal
echo "e2e: passed"
