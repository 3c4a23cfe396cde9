#!/usr/bin/env bash
# Autotune through the console in tmux, flying the firmware in qrsim (issue 34): calibrate, full
# control, climb and hover, '=' flies the identification (9.1 s); the parameter screen then shows
# the fitted models, the gains flown beside the new ones and the figures before and after; ^T sends
# the new gains and the QR reports them; ^R sends the old ones back and the QR reports those.
set -euo pipefail

qrterm=${1:?usage: e2e_autotune.sh QRTERM QRSIM}
sim=${2:?usage: e2e_autotune.sh QRTERM QRSIM}
[[ -x $qrterm && -x $sim ]] || { echo "e2e: no qrterm at $qrterm or no qrsim at $sim" >&2; exit 1; }

source "$(dirname "$0")/e2e_lib.sh"
e2e_start

export LC_ALL=C
e2e_pane "$qrterm" --sim "$sim" --no-joystick --log-dir "$work/logs" --params "$work/params.txt"
wait_for 'MODE +safe ' 30 "start: safe"
keys 3
wait_for 'QR calibrated' 30 "calibrated"
wait_for 'MODE +safe ' 5 "back in safe"
keys 5
wait_for 'MODE +full' 3 "full control"
for _ in $(seq 54); do keys a; done
wait_for 'hover lift [0-9]+' 5 "airborne: the hover lift the QR learnt"
keys Home
keys =
wait_for 'MODE +autotune' 3 "= enters autotune"
wait_for 'autotune: recording the identification' 2 "the console records it"
wait_for 'autotune: new gains on the parameter screen' 15 "recorded, fitted, designed"
wait_for 'MODE +full' 2 "the QR back in full control by itself"

keys Tab Tab
wait_for 'PARAMETERS' 2 "Tab Tab: the parameter screen"
wait_for 'model gain/lag: roll [0-9.e-]+/[0-9.]+ms pitch [0-9.e-]+/[0-9.]+ms yaw [0-9.e-]+/[0-9.]+ms' 1 "the fitted models"
wait_for '^autotune +before +new +\| +before +new' 1 "old and new side by side"
wait_for '^roll PM [0-9.]+->[0-9.]+ deg  GM [0-9.inf]+->[0-9.inf]+ dB  rise [0-9.]+->[0-9.]+ s' 1 "roll's figures before and after"
wait_for '^yaw  PM [0-9.]+->[0-9.]+ deg' 1 "yaw's figures"
shown=$(screen)
# The new roll_pitch_p1 as the screen shows it, and the old one.
read -r old new < <(sed -nE 's/^roll_pitch_p1 +([0-9.]+) +([0-9.]+).*/\1 \2/p' <<<"$shown" | head -1)
[[ -n $old && -n $new ]] || fail "no roll_pitch_p1 row with old and new"
[[ $old != "$new" ]] || fail "roll_pitch_p1 unchanged: $old"
echo "e2e: ok: roll_pitch_p1 $old -> $new"

# The list's roll_pitch_p1 row (the second; the cursor is on the first) reads `value  read back`
# once the QR has reported the value the console holds: wait until that value is `want`.
read_back_is() {
  local want=$1 what=$2 deadline=$((SECONDS + 6))
  until screen | awk -v w="$want" '$1 == "roll_pitch_p1" && $3 == "read" && $4 == "back" && ($2 - w) ^ 2 < 1e-6 { ok = 1 }
                                   END { exit !ok }'; do
    ((SECONDS <= deadline)) || fail "$what: roll_pitch_p1 not read back as $want"
    sleep 0.1
  done
  echo "e2e: ok: $what (roll_pitch_p1 $want, read back from the QR)"
}
read_back_is "$old" "the gains flown are those in force"
# ^T: the six new values go up, each acked, then read back from the QR.
keys C-t
wait_for 'the new gains sent: \^R goes back' 2 "^T: the new gains to the QR"
read_back_is "$new" "the QR holds the new gains"
grep -q "yaw_i = " "$work/logs/console.log" || fail "yaw_i not sent"
# ^R: the six values flown before go up again.
keys C-r
wait_for 'the gains before sent again' 2 "^R: back"
read_back_is "$old" "the QR holds the gains before again"
keys Escape
exit_and_check_terminal
echo "e2e: passed"
