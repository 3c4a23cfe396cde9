#!/usr/bin/env bash
# qrterm started without a terminal (from a script, a pipe, ssh without -t) said "qrterm: qrterm
# needs a terminal" (issue 36): it now says which end is not one and what to do, with status 2.
# usage: no_terminal_test.sh QRTERM
set -uo pipefail
qrterm=${1:?usage: no_terminal_test.sh QRTERM}
out=$("$qrterm" --no-joystick </dev/null 2>&1 >/dev/null); status=$?
echo "$out"
[[ $status == 2 ]] || { echo "FAILED: status $status, not 2" >&2; exit 1; }
[[ $out == "qrterm: standard input is not a terminal: run qrterm in a terminal window"* ]] ||
  { echo "FAILED: the message" >&2; exit 1; }
[[ $out != *"qrterm: qrterm"* ]] || { echo "FAILED: the program named twice" >&2; exit 1; }
out=$("$qrterm" --help </dev/null 2>&1); status=$?
[[ $status == 0 && $out == usage:* ]] || { echo "FAILED: --help without a terminal: $status" >&2; exit 1; }
