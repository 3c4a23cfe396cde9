#!/usr/bin/env bash
# The orientation check through qrterm in tmux (docs/console.md, "The orientation check"), against
# a simulated vehicle whose IMU board is mounted turned 90 deg clockwise (imu_mount_yaw_deg = 90)
# and a parameter file that says nothing of it:
#   9 in safe opens the check; Enter three times, and the simulator's hand tilts the QR right side
#   down, nose up and nose right; the screen reads pitch -, roll +, yaw + and names the mounting,
#   imu_orientation = 1; Enter sets it: the QR reports it back and the parameter file holds it;
#   Tab returns to the cockpit; x exits.
#
# usage: e2e_orientation.sh QRTERM QRSIM
set -euo pipefail

qrterm=${1:?usage: e2e_orientation.sh QRTERM QRSIM}
sim=${2:?usage: e2e_orientation.sh QRTERM QRSIM}

[[ -x $qrterm ]] || { echo "e2e: no qrterm at $qrterm" >&2; exit 1; }
[[ -x $sim ]] || { echo "e2e: no simulator at $sim" >&2; exit 1; }

source "$(dirname "$0")/e2e_lib.sh"
e2e_start

cp "$(dirname "$0")/../../sim/vehicles/in4073.txt" "$work/turned.txt"
echo "imu_mount_yaw_deg = 90" >>"$work/turned.txt"
echo "yaw_p = 250" >"$work/params.txt"
e2e_pane "$qrterm" --sim "$sim" --sim-arg --vehicle --sim-arg "$work/turned.txt" --no-joystick \
  --log-dir "$work/logs" --params "$work/params.txt"

# 1. 9 in safe: the check's screen, with what is in force.
wait_for 'MODE +safe ' 30 "start: the screen shows safe"
find_sim_pid
keys 9
wait_for 'ORIENTATION CHECK +imu_orientation 0 in force' 3 "9 opens the orientation check"
wait_for '>1 tilt right \(roll \+\)' 1 "step 1 asked"

# 2. Each Enter: the simulator's hand moves the QR; the step's row says what the QR read.
keys Enter
wait_for '^ 1 tilt right \(roll \+\).* pitch -' 5 "step 1: tilted right, the QR read pitch -"
keys Enter
wait_for '^ 2 nose up \(pitch \+\).* roll \+' 5 "step 2: nose up, the QR read roll +"
keys Enter
wait_for '^ 3 turn right \(yaw \+\).* yaw \+  ok' 5 "step 3: nose right, the QR read yaw +"

# 3. The verdict names the mounting; Enter sets it, the QR takes it, the file keeps it.
wait_for 'turned 90 deg clockwise \(X arrow right\): imu_orientation = 1' 1 "the mounting named"
wait_for 'Enter: set imu_orientation = 1' 1 "setting it offered"
keys Enter
wait_for 'imu_orientation = 1 sent to the QR and kept in' 3 "set"
grep -qx 'imu_orientation = 1' "$work/params.txt" || fail "the parameter file does not hold imu_orientation = 1"
grep -qx 'yaw_p = 250' "$work/params.txt" || fail "the parameter file lost yaw_p = 250"
echo "e2e: ok: the parameter file holds imu_orientation = 1 beside its yaw_p"
keys p
deadline=$((SECONDS + 5))
until grep -q 'parameters read back: the QR' "$work/logs/console.log"; do
  ((SECONDS <= deadline)) || fail "no read-back of the parameters"
  sleep 0.1
done
grep -q "parameters read back: the QR has the console's values" "$work/logs/console.log" ||
  fail "the QR's parameters differ from the console's"
! grep -q 'QR refused' "$work/logs/console.log" || fail "the QR refused a request"
echo "e2e: ok: the QR reports every parameter as the console has it, imu_orientation 1 with them"

# 4. Tab back to the cockpit; x exits.
keys Tab
wait_for 'cockpit \(Tab\)' 2 "Tab returns to the cockpit"
exit_and_check_terminal
