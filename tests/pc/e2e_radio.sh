#!/usr/bin/env bash
# The radio as the pilot, through qrterm in tmux (qrsim --serve --rc crsf, docs/safety.md rule 17):
#   the parameter file makes the radio the pilot -> the screen shows RADIO FLIES and the radio's
#   link up, and the battery row its charge; the radio screen, before the first arming, shows the
#   sixteen channels and follows the simulated transmitter: the sticks' ends as the console's trims
#   move its sticks, the arm and mode switches as its keys move them; 3 calibrates (the PC's); 5
#   moves the simulated radio's switches and the QR arms full control with the arm switch ON on the
#   screen; the lift keys fly it up through the radio (the simulator's truth height rises); m puts
#   the arm switch off: panic (arm switch off), then safe; x exits.
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
# The simulated pack starts at 85 % (sim/vehicles/in4073.txt); how long it lasts is not known on
# the ground.
wait_for '^battery +12\.[0-9]{2} V 3S 8[0-9] % -- left ' 5 "the battery row: volts, cells, charge, no time left yet"

# 2. The radio screen (Tab Tab Tab): the channels as bars in microseconds with the controls the
#    parameters give them, the switches as the firmware reads them; the console's trims are the
#    simulated transmitter's sticks, so full roll right and full lift show which ends each stick
#    reached; 4 moves its switches to yaw control and arm on (the QR, not calibrated, does not
#    arm), m the arm switch off.
keys Tab Tab Tab
wait_for 'RADIO +16 channels at 25 Hz' 10 "Tab Tab Tab: the radio screen streams the sixteen channels"
wait_for '^ 3 lift +988 us \.+ +988\.\.988 +no high end' 3 "the lift stick at its low stop"
wait_for '^ 5 arm +988 us \.+ off \(low\)' 1 "the arm switch off"
wait_for '^ 6 mode +988 us \.+ low: manual' 1 "the mode switch low: manual"
wait_for '^16 +1500 us #+\.+$' 1 "channel 16, read by nobody, in the middle"
keys $(printf 'Right %.0s' $(seq 100))
keys $(printf 'PageUp %.0s' $(seq 10))
wait_for '^ 1 roll +2012 us #+ 1500\.\.2012 no low end' 3 "full roll right: its high end, not its low"
wait_for '^ 3 lift +2012 us #+ +988\.\.2012 both ends' 3 "full lift: both ends of the lift"
keys c 4
wait_for '^ 6 mode +1500 us #+\.+ centre: yaw control' 3 "4: the mode switch to the centre, yaw control"
wait_for '^ 5 arm +2012 us #+ ON \(high\)' 3 "and the arm switch on"
wait_for '^ 1 roll +1500 us #+\.+ 1500\.\.2012 no low end' 1 "c: the roll stick back in the middle, its ends kept"
keys m
wait_for '^arm ch 5: off \(low\) +mode ch 6: centre: yaw control' 3 "m: the arm switch off"
keys Tab
wait_for 'cockpit \(Tab\)' 2 "Tab: back to the cockpit"

# 3. Calibration stays the PC's.
keys 3
wait_for 'QR calibrated' 30 "calibration done"
wait_for 'MODE +safe ' 5 "back in safe after calibration"

# 4. 5: the radio's mode switch to full control, its arm switch off and on: the QR arms.
keys 5
wait_for 'sim radio: mode switch to full control' 3 "5 moves the radio's switches"
wait_for 'MODE +full control ' 3 "the arm switch arms full control"
wait_for 'RADIO FLIES +link up +arm ON' 3 "the screen shows the arm switch on"

# 5. Lift through the radio: the simulator's truth height rises above 0.3 m.
ground=$(truth_height)
[[ -n $ground ]] || fail "no truth height on the screen"
for _ in $(seq 6); do keys PageUp; done
deadline=$((SECONDS + 8))
while awk "BEGIN { exit !($(truth_height) < $ground + 0.3) }"; do
  ((SECONDS <= deadline)) || fail "the QR did not climb through the radio (truth height $(truth_height) m)"
  sleep 0.1
done
echo "e2e: ok: climbed through the radio from $ground m to $(truth_height) m"

# 6. m: the arm switch off in flight is the emergency stop.
keys m
wait_for 'MODE +panic ' 3 "m: the arm switch off panics"
grep -q 'panic (arm switch off)' "$work/logs/console.log" || fail "the QR did not say the arm switch off was the cause"
echo "e2e: ok: the QR said panic (arm switch off)"
for _ in $(seq 6); do keys PageDown; done
wait_for 'MODE +safe ' 10 "panic settles in safe"

# 7. x exits and the terminal is given back.
exit_and_check_terminal
