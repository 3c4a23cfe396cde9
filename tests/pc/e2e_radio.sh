#!/usr/bin/env bash
# The radio as the pilot, through qrterm in tmux (qrsim --serve --rc crsf, docs/safety.md rule 17):
#   the parameter file makes the radio the pilot -> the screen shows RADIO FLIES and the radio's
#   link up; 3 calibrates (the PC's); 5 moves the simulated radio's switches and the QR arms full
#   control with the arm switch ON on the screen; the lift keys fly it up through the radio (the
#   simulator's truth height rises); m puts the arm switch off: panic (arm switch off), then safe;
#   x exits.
#
# usage: e2e_radio.sh QRTERM QRSIM
set -euo pipefail

qrterm=${1:?usage: e2e_radio.sh QRTERM QRSIM}
sim=${2:?usage: e2e_radio.sh QRTERM QRSIM}

[[ -x $qrterm ]] || { echo "e2e: no qrterm at $qrterm" >&2; exit 1; }
[[ -x $sim ]] || { echo "e2e: no simulator at $sim" >&2; exit 1; }

source "$(dirname "$0")/e2e_lib.sh"
e2e_start

truth_height() { screen | sed -nE 's/.*truth roll .* height ([0-9.]+) m.*/\1/p' | head -1; }

echo "pilot = 1" >"$work/params.txt"
e2e_pane "$qrterm" --sim "$sim" --sim-arg --rc --sim-arg crsf --no-joystick --log-dir "$work/logs" \
  --params "$work/params.txt"

# 1. The console's parameters make the radio the pilot (in safe), and the console's sticks reach
#    the QR through the simulator's radio: its link is up.
wait_for 'MODE +safe ' 30 "start: the screen shows safe"
find_sim_pid
wait_for 'RADIO FLIES +link up +arm off' 10 "the radio flies, its link up, the arm switch off"

# 2. Calibration stays the PC's.
keys 3
wait_for 'QR calibrated' 30 "calibration done"
wait_for 'MODE +safe ' 5 "back in safe after calibration"

# 3. 5: the radio's mode switch to full control, its arm switch off and on: the QR arms.
keys 5
wait_for 'sim radio: mode switch to full control' 3 "5 moves the radio's switches"
wait_for 'MODE +full control ' 3 "the arm switch arms full control"
wait_for 'RADIO FLIES +link up +arm ON' 3 "the screen shows the arm switch on"

# 4. Lift through the radio: the simulator's truth height rises above 0.3 m.
ground=$(truth_height)
[[ -n $ground ]] || fail "no truth height on the screen"
for _ in $(seq 6); do keys PageUp; done
deadline=$((SECONDS + 8))
while awk "BEGIN { exit !($(truth_height) < $ground + 0.3) }"; do
  ((SECONDS <= deadline)) || fail "the QR did not climb through the radio (truth height $(truth_height) m)"
  sleep 0.1
done
echo "e2e: ok: climbed through the radio from $ground m to $(truth_height) m"

# 5. m: the arm switch off in flight is the emergency stop.
keys m
wait_for 'MODE +panic ' 3 "m: the arm switch off panics"
grep -q 'panic (arm switch off)' "$work/logs/console.log" || fail "the QR did not say the arm switch off was the cause"
echo "e2e: ok: the QR said panic (arm switch off)"
for _ in $(seq 6); do keys PageDown; done
wait_for 'MODE +safe ' 10 "panic settles in safe"

# 6. x exits and the terminal is given back.
exit_and_check_terminal
