#!/usr/bin/env bash
# The devboard's printed hint (issue 17, what a newcomer tripped over): `scripts/devboard` prints
# the command that flies the board, and on a machine without a joystick qrterm alone refuses to
# start. The hint for a serial line (`scripts/devboard --hint PTY`, the line the interactive run
# prints) is run here exactly as printed, from a folder where its relative path resolves, against
# the fake QR on a pty: the console must start, show safe with the link up, and exit with 0.
#
# usage: e2e_devboard_hint.sh FAKE_QR   (the qrterm it runs is the one the hint names)
set -euo pipefail

fake=${1:?usage: e2e_devboard_hint.sh FAKE_QR}
root=$(cd "$(dirname "$0")/../.." && pwd)
[[ -x $fake ]] || { echo "e2e: no fake QR at $fake" >&2; exit 1; }

source "$(dirname "$0")/e2e_lib.sh"
e2e_start

# The board's side: the fake QR on a pty, as QEMU's UART would be.
"$fake" --serve >"$work/fake.out" 2>&1 &
sim_pid=$!  # e2e_cleanup stops it
pty=""
for _ in $(seq 50); do
  pty=$(sed -nE 's/.*serial on (\/dev\/[^ ]+).*/\1/p' "$work/fake.out" | head -1)
  [[ -n $pty ]] && break
  sleep 0.1
done
[[ -n $pty ]] || fail "the fake QR gave no pty: $(cat "$work/fake.out")"

hint=$("$root/scripts/devboard" --hint "$pty")
echo "e2e: the hint: $hint"
command=$(sed -nE 's/^devboard: fly it with  (.*[^ ]) +\(Ctrl-C here stops the board\)$/\1/p' <<<"$hint")
[[ -n $command ]] || fail "no command in the hint '$hint'"
read -ra words <<<"$command"
if [[ -e /dev/input/js0 ]]; then
  echo "e2e: this machine has /dev/input/js0: the hint is run as printed for a machine with a joystick"
else
  echo "e2e: no joystick on this machine"
fi

# As a newcomer runs it: from the checkout (here a folder whose build/ is the checkout's, so the
# session's logs and parameter file stay out of the tree).
mkdir -p "$work/checkout"
ln -s "$root/build" "$work/checkout/build"
[[ -x $work/checkout/${words[0]} ]] || fail "the hint names ${words[0]}, which is not built"
(cd "$work/checkout" && e2e_pane "${words[@]}")
wait_for 'MODE +safe ' 15 "the hinted command starts the console: safe"
wait_for 'LINK up' 5 "and talks to the board"
keys x
wait_for 'QRTERM ENDED' 5 "x exits"
[[ $(cat "$work/status") == 0 ]] || fail "the hinted qrterm ended with status $(cat "$work/status")"
echo "e2e: passed"
