#!/usr/bin/env bash
# qrterm driven in tmux as a pilot would, its screen captured and asserted:
#   start -> the screen shows safe; 3 calibrates; 2 (lift at zero) enters manual; a pressed N times
#   raises the engines; ESC -> panic -> safe; the simulator killed -> LINK LOST within 2 s;
#   x exits and the terminal is given back as it was.
#
# usage: e2e_console.sh QRTERM SIMULATOR
#   SIMULATOR is anything that speaks like `qrsim --serve` (first line "... serial on /dev/pts/N"):
#   build/host/qr/qrsim, or the fake QR build/host/tests/pc/fake-qr.
# A private tmux server (tmux -L <unique name>) and a temporary folder; both go away at the end,
# whatever happens.
set -euo pipefail

qrterm=${1:?usage: e2e_console.sh QRTERM SIMULATOR}
sim=${2:?usage: e2e_console.sh QRTERM SIMULATOR}
presses=${E2E_LIFT_PRESSES:-20}

command -v tmux >/dev/null || { echo "e2e: tmux is not installed (scripts/bootstrap installs it)" >&2; exit 1; }
[[ -x $qrterm ]] || { echo "e2e: no qrterm at $qrterm" >&2; exit 1; }
[[ -x $sim ]] || { echo "e2e: no simulator at $sim" >&2; exit 1; }

socket="qrterm-e2e-$$-$RANDOM"
work=$(mktemp -d /tmp/qrterm-e2e.XXXXXX)
tmux=(tmux -L "$socket")
sim_pid=""

cleanup() {
  "${tmux[@]}" kill-server 2>/dev/null || true
  # The simulator is qrterm's child; if qrterm could not stop it, it is ours to stop.
  if [[ -n $sim_pid ]] && kill -0 "$sim_pid" 2>/dev/null; then kill "$sim_pid" 2>/dev/null || true; fi
  rm -rf "$work"
}
trap cleanup EXIT

screen() { "${tmux[@]}" capture-pane -p -t e2e; }

fail() {
  echo "e2e: FAILED: $*" >&2
  echo "---- screen ----" >&2
  screen >&2 || true
  echo "---- console.log ----" >&2
  cat "$work/logs/console.log" >&2 2>/dev/null || true
  exit 1
}

# Waits until the screen matches the regular expression (grep -E), at most `seconds`.
wait_for() {
  local pattern=$1 seconds=$2 what=$3
  local deadline=$((SECONDS + seconds + 1)) start=$EPOCHREALTIME
  while ((SECONDS <= deadline)); do
    if screen | grep -Eq -- "$pattern"; then
      echo "e2e: ok: $what ($(awk "BEGIN { printf \"%.1f\", $EPOCHREALTIME - $start }") s)"
      return 0
    fi
    sleep 0.1
  done
  fail "$what: no /$pattern/ within $seconds s"
}

engine_front() { screen | sed -nE 's/^front +([0-9]+) .*/\1/p'; }

# The pane runs a shell that records the terminal's settings before and after qrterm, and how
# qrterm ended, then stays open for the capture.
cat >"$work/pane.sh" <<EOF
stty -g >"$work/stty.before"
"$qrterm" --sim "$sim" --no-joystick --log-dir "$work/logs" --params "$work/params.txt"
echo \$? >"$work/status"
stty -g >"$work/stty.after"
echo "QRTERM ENDED"
sleep 600
EOF

"${tmux[@]}" -f /dev/null new-session -d -s e2e -x 80 -y 24 "bash $work/pane.sh"

# 1. Start: the simulator answers and the screen shows safe.
wait_for 'MODE +safe' 30 "start: the screen shows safe"
wait_for 'LINK up' 5 "link up"
for _ in $(seq 50); do
  sim_pid=$(sed -nE 's/.*simulator pid ([0-9]+).*/\1/p' "$work/logs/console.log" 2>/dev/null | head -1)
  [[ -n $sim_pid ]] && break
  sleep 0.1
done
[[ -n $sim_pid ]] || fail "no simulator pid in console.log"

# 2. Calibration: 3, then the QR reports itself calibrated and back in safe.
"${tmux[@]}" send-keys -t e2e 3
wait_for 'QR mode: calibration' 3 "3 asks for calibration"
wait_for 'QR calibrated' 30 "calibration done"
wait_for 'MODE +safe' 5 "back in safe after calibration"

# 3. Manual with the lift at zero.
"${tmux[@]}" send-keys -t e2e 2
wait_for 'MODE +manual' 3 "2 enters manual"
before=$(engine_front)
[[ $before =~ ^[0-9]+$ ]] || fail "no engine value on the screen"

# 4. Lift: a, N times, raises the engines.
for _ in $(seq "$presses"); do "${tmux[@]}" send-keys -t e2e a; done
wait_for "sending +lift +$((presses * 10)) " 3 "$presses presses of a give lift $((presses * 10))"
deadline=$((SECONDS + 5))
while (($(engine_front) <= before)); do
  ((SECONDS <= deadline)) || fail "engines did not rise above $before"
  sleep 0.1
done
echo "e2e: ok: engines rose from $before to $(engine_front)"

# 5. ESC: panic, then the QR settles in safe by itself.
"${tmux[@]}" send-keys -t e2e Escape
wait_for 'MODE +panic' 3 "ESC: panic"
wait_for 'MODE +safe' 10 "panic settles in safe"

# 6. The simulator dies: LINK LOST within 2 s.
kill "$sim_pid"
wait_for 'LINK LOST' 2 "simulator killed: LINK LOST"

# 7. x exits and the terminal is given back.
"${tmux[@]}" send-keys -t e2e x
wait_for 'QRTERM ENDED' 5 "x exits"
[[ $(cat "$work/status") == 0 ]] || fail "qrterm ended with status $(cat "$work/status")"
[[ $("${tmux[@]}" display-message -p -t e2e '#{alternate_on}') == 0 ]] || fail "still on the alternate screen"
cmp -s "$work/stty.before" "$work/stty.after" || fail "terminal settings not restored"
echo "e2e: ok: terminal restored"

# The files of the session are there.
for file in console.log rx.hex telemetry.csv; do
  [[ -s $work/logs/$file ]] || fail "no $file in the log folder"
done
[[ -s $work/params.txt ]] || fail "parameter file not written at exit"
echo "e2e: passed"
