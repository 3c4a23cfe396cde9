#!/usr/bin/env bash
# The motor test screen (issue 33), in tmux, on the firmware in qrsim: 9 opens it in safe, y says
# the propellers are off, a digit spins that engine for the QR's 2 s, and the screen names the rotor
# the simulator's truth saw turn and its way; the pilot confirms it. Any key stops a spinning
# engine at once.
set -euo pipefail

qrterm=${1:?usage: e2e_motor_test.sh QRTERM QRSIM}
sim=${2:?usage: e2e_motor_test.sh QRTERM QRSIM}
[[ -x $qrterm && -x $sim ]] || { echo "e2e: no qrterm at $qrterm or no qrsim at $sim" >&2; exit 1; }

source "$(dirname "$0")/e2e_lib.sh"
e2e_start

export LC_ALL=C
e2e_pane "$qrterm" --sim "$sim" --no-joystick --log-dir "$work/logs" --params "$work/params.txt"
wait_for 'MODE +safe ' 30 "start: safe"

keys 9
wait_for 'Are the propellers OFF\?' 3 "9: the motor test asks for the propellers first"
keys y
wait_for '1-4: spin that engine' 2 "y: engines to choose"

keys 2
wait_for 'engine 2 \(right\) spinning at 10 %' 2 "2: the right engine spins"
wait_for 'MODE +motor test ' 2 "the QR in its motor test"
wait_for 'sim: rotor 2 \(right\) turned counter-clockwise, as engine 2 must' 3 "the simulator names the right rotor"
wait_for 'Did the right rotor turn, counter-clockwise seen from above\?' 4 "after its 2 s the QR stops it by itself"
wait_for 'MODE +safe ' 1 "the QR back in safe"
keys y
wait_for 'engine 2  right  counter-clockwise  confirmed' 2 "y: the right engine confirmed"

keys 1
wait_for 'engine 1 \(front\) spinning' 2 "1: the front engine spins"
wait_for 'MODE +motor test ' 2 "the QR in its motor test"
keys z
wait_for 'Did the front rotor turn, clockwise seen from above\?' 1 "any key stops it"
wait_for 'MODE +safe ' 1 "at once: the QR in safe"
wait_for '^ +0  engine 1  front' 1 "the front engine at 0"
keys n
wait_for 'engine 1  front  clockwise          WRONG' 2 "n: the front engine marked wrong"

keys q
wait_for '^front +0 ' 1 "q: back to the cockpit's engine rows"
exit_and_check_terminal
echo "e2e: passed"
