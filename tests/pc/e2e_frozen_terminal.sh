#!/usr/bin/env bash
# A terminal that stops taking output must not stop the heartbeat. The tmux server is stopped
# (SIGSTOP), so nothing reads what qrterm writes to its terminal; once qrterm's screen thread is
# seen blocked writing, the QR (the fake, which panics 250 ms after the last valid frame) must
# still be in manual, and stay there, and the console must not have lost the link.
#
# usage: e2e_frozen_terminal.sh QRTERM FAKE_QR
# Exit 77 (skipped) when the kernel does not show where a thread waits (/proc/PID/wchan).
set -euo pipefail

qrterm=${1:?usage: e2e_frozen_terminal.sh QRTERM FAKE_QR}
sim=${2:?usage: e2e_frozen_terminal.sh QRTERM FAKE_QR}

source "$(dirname "$0")/e2e_lib.sh"
e2e_start
tmux_pid=""
thaw() { [[ -n $tmux_pid ]] && kill -CONT "$tmux_pid" 2>/dev/null || true; }
trap 'thaw; e2e_cleanup' EXIT

e2e_pane "$qrterm" --sim "$sim" --sim-arg --chatty --no-joystick --log-dir "$work/logs" --params "$work/params.txt"
"${tmux[@]}" resize-window -t e2e -x 250 -y 80  # a big screen fills the terminal's buffer sooner
wait_for 'MODE +safe ' 30 "start"
keys 2
wait_for 'MODE +manual ' 3 "manual"
qrterm_pid=$(cat "$work/qrterm.pid")
[[ $(cat "/proc/$qrterm_pid/wchan" 2>/dev/null) =~ [a-z] ]] || { echo "e2e: skipped: /proc/PID/wchan shows nothing here"; exit 77; }

tmux_pid=$("${tmux[@]}" display-message -p '#{pid}')
kill -STOP "$tmux_pid"
blocked=""
for _ in $(seq 100); do
  if [[ $(cat "/proc/$qrterm_pid/task/$qrterm_pid/wchan") == wait_woken ]]; then blocked=yes; break; fi
  sleep 0.1
done
[[ -n $blocked ]] || fail "the terminal never held qrterm up (nothing to test)"
echo "e2e: ok: qrterm's screen thread is blocked writing to the frozen terminal"
sleep 2  # eight link timeouts of the QR
thaw
tmux_pid=""

wait_for 'MODE +manual ' 5 "the QR is still in manual"
grep -q 'QR mode: panic' "$work/logs/console.log" && fail "the QR panicked while the terminal was frozen"
grep -q 'LINK LOST' "$work/logs/console.log" && fail "the console lost the link while the terminal was frozen"
echo "e2e: ok: no panic, no link loss"
exit_and_check_terminal
echo "e2e: passed"
