#!/usr/bin/env bash
# The motor test screen (issue 33), in tmux, on the firmware in qrsim flying a miswired vehicle
# with DShot ESCs: engines 2 and 4 swapped at their outputs, the back motor turning the wrong way.
# 6 opens the screen in safe, y says the propellers are off, a digit spins that engine, and the
# screen names the rotor the simulator's truth saw turn and its way. Engine 1 is right (the QR ends
# its 2 s by itself); engine 2 turns the left rotor (a key stops it at once); engine 3 turns the
# wrong way, and its ESC's spin direction set from the screen puts it right.
set -euo pipefail

qrterm=${1:?usage: e2e_motor_test.sh QRTERM QRSIM}
sim=${2:?usage: e2e_motor_test.sh QRTERM QRSIM}
[[ -x $qrterm && -x $sim ]] || { echo "e2e: no qrterm at $qrterm or no qrsim at $sim" >&2; exit 1; }

source "$(dirname "$0")/e2e_lib.sh"
e2e_start

{
  cat "$(dirname "$0")/../../sim/vehicles/in4073.txt"
  echo "motor_outputs = 0 3 2 1"
  echo "motor_reversed = 0 0 1 0"
} >"$work/miswired.txt"

export LC_ALL=C
e2e_pane "$qrterm" --sim "$sim" --sim-arg --vehicle --sim-arg "$work/miswired.txt" --sim-arg --esc --sim-arg dshot \
  --no-joystick --log-dir "$work/logs" --params "$work/params.txt"
wait_for 'MODE +safe ' 30 "start: safe"

keys 6
wait_for 'Are the propellers OFF\?' 3 "6: the motor test asks for the propellers first"
keys y
wait_for '1-4: spin that engine' 2 "y: engines to choose"

keys 1
wait_for 'engine 1 \(front\) spinning at 10 %' 2 "1: the front engine spins"
wait_for 'MODE +motor test ' 2 "the QR in its motor test"
wait_for 'sim: rotor 1 \(front\) turned clockwise, as engine 1 must' 3 "the simulator names the front rotor"
wait_for 'Did the front rotor turn, clockwise seen from above\?' 4 "after its 2 s the QR stops it by itself"
wait_for 'MODE +safe ' 1 "the QR back in safe"
keys y
wait_for 'engine 1  front  clockwise          confirmed' 2 "y: the front engine confirmed"

keys 2
wait_for 'sim: rotor 4 \(left\) turned counter-clockwise: the wrong rotor for engine 2' 3 \
  "engine 2 turns the left rotor: miswired"
keys z
wait_for 'Did the right rotor turn' 1 "any key stops it"
wait_for 'MODE +safe ' 1 "at once: the QR in safe"
keys n
wait_for 'The wrong way\? Its DShot ESC, saved: 1 normal  2 reversed' 2 "n: the ESC's direction offered (DShot)"
keys x
wait_for 'engine 2  right  counter-clockwise  WRONG' 2 "another key: engine 2 marked wrong, its ESC left as it is"

keys 3
wait_for 'sim: rotor 3 \(back\) turned counter-clockwise: the wrong way' 3 "engine 3 turns its rotor the wrong way"
keys z
wait_for 'Did the back rotor turn' 1 "stopped"
keys n 2
wait_for 'ESC 3: spin direction 2, saved' 3 "2: the QR sets and saves the ESC's direction"
keys 3
wait_for 'sim: rotor 3 \(back\) turned clockwise, as engine 3 must' 3 "spun again: the back rotor turns its way"
keys z y
wait_for 'engine 3  back   clockwise          confirmed' 2 "y: engine 3 confirmed"

keys q
wait_for '^front +0 ' 1 "q: back to the cockpit's engine rows"
exit_and_check_terminal
echo "e2e: passed"
