#!/usr/bin/env bash
# qrterm driven in tmux as a pilot would, its screen captured and asserted:
#   start -> the screen shows safe (and, flying qrsim, its truth line; n pushes); 3 calibrates
#   (and the height row shows the height estimate, or -- from the fake QR);
#   2 (lift at zero) enters manual; a pressed N times raises the engines; ESC -> panic -> safe;
#   the simulator killed -> LINK LOST within 2 s; x exits and the terminal is given back as it was.
#
# usage: e2e_console.sh QRTERM SIMULATOR
#   SIMULATOR is anything that speaks like `qrsim --serve` (first line "... serial on /dev/pts/N"):
#   build/host/qr/qrsim, or the fake QR build/host/tests/pc/fake-qr.
# A private tmux server (tmux -L <unique name>) and a temporary folder; both go away at the end,
# whatever happens (e2e_lib.sh).
set -euo pipefail

qrterm=${1:?usage: e2e_console.sh QRTERM SIMULATOR}
sim=${2:?usage: e2e_console.sh QRTERM SIMULATOR}
presses=${E2E_LIFT_PRESSES:-20}

[[ -x $qrterm ]] || { echo "e2e: no qrterm at $qrterm" >&2; exit 1; }
[[ -x $sim ]] || { echo "e2e: no simulator at $sim" >&2; exit 1; }

source "$(dirname "$0")/e2e_lib.sh"
e2e_start

engine_front() { screen | sed -nE 's/^front +([0-9]+) .*/\1/p'; }

e2e_pane "$qrterm" --sim "$sim" --no-joystick --log-dir "$work/logs" --params "$work/params.txt"

# 1. Start: the simulator answers and the screen shows safe.
wait_for 'MODE +safe ' 30 "start: the screen shows safe"
wait_for 'LINK up' 5 "link up"
find_sim_pid
# The simulator's truth line (qrsim's truth channel; the fake QR has none), and n pushes.
if [[ $(basename "$sim") == qrsim ]]; then
  wait_for 'truth roll [-+][0-9.]+ pitch [-+][0-9.]+ yaw [-+][0-9.]+ height [0-9.]+ m' 5 "the simulator's truth line"
  keys n
  wait_for 'sim: push 0.3 N m about roll' 3 "n pushes the simulated QR"
fi

# 2. Calibration: 3, then the QR reports itself calibrated and back in safe.
keys 3
wait_for 'QR mode: calibration' 3 "3 asks for calibration"
wait_for 'QR calibrated' 30 "calibration done"
wait_for 'MODE +safe ' 5 "back in safe after calibration"
# The height estimate's row: a figure from the firmware (qrsim), or -- from the fake QR.
if [[ $(basename "$sim") == qrsim ]]; then
  wait_for 'height +[-+][0-9.]+ m  climb [-+][0-9.]+ m/s +height hold off \(7\)' 5 "the height row"
else
  wait_for 'height +-- m' 5 "the height row, empty"
fi

# 3. Manual with the lift at zero.
keys 2
wait_for 'MODE +manual ' 3 "2 enters manual"
before=$(engine_front)
[[ $before =~ ^[0-9]+$ ]] || fail "no engine value on the screen"

# 4. Lift: a, N times, raises the engines.
for _ in $(seq "$presses"); do keys a; done
wait_for "sending +lift +$((presses * 10)) " 3 "$presses presses of a give lift $((presses * 10))"
deadline=$((SECONDS + 5))
while (($(engine_front) <= before)); do
  ((SECONDS <= deadline)) || fail "engines did not rise above $before"
  sleep 0.1
done
echo "e2e: ok: engines rose from $before to $(engine_front)"

# 5. ESC: panic, then the QR settles in safe by itself.
keys Escape
wait_for 'MODE +panic ' 3 "ESC: panic"
wait_for 'MODE +safe ' 10 "panic settles in safe"

# 6. The simulator dies: LINK LOST within 2 s.
kill "$sim_pid"
wait_for 'LINK LOST' 2 "simulator killed: LINK LOST"

# 7. x exits and the terminal is given back.
exit_and_check_terminal

# The files of the session are there.
for file in console.log rx.hex telemetry.csv; do
  [[ -s $work/logs/$file ]] || fail "no $file in the log folder"
done
[[ -s $work/params.txt ]] || fail "parameter file not written at exit"
echo "e2e: passed"
