#!/usr/bin/env bash
# The cockpit's rough edges (issue 36), in tmux against the fake QR at 80x24, as a pilot meets them:
#   - log folders kept to 20: two of 21 earlier session folders go at start, a folder of another
#     name stays, and the log says so;
#   - the devboard's figures (the fake QR as qrsim --devboard --core-mhz 16 would be): the CPU row
#     is the core's load at its clock, b labels the task figures RV32 instructions with the tick;
#   - the help overlay: Tab named, columns with room between them;
#   - F1 and Delete named, not "key code 265/330";
#   - the parameter screen without a parameter file: no file column;
#   - the plot's Tab completes as far as the names agree and lists them;
#   - eight gain steps are one log line;
#   - 0 in flight says the pilot asked for the panic, with the key;
#   - the exit names the undo of the change the session saved.
# usage: e2e_cockpit_edges.sh QRTERM FAKE_QR
set -euo pipefail

qrterm=${1:?usage: e2e_cockpit_edges.sh QRTERM FAKE_QR}
sim=${2:?usage: e2e_cockpit_edges.sh QRTERM FAKE_QR}
[[ -x $qrterm && -x $sim ]] || { echo "e2e: no qrterm at $qrterm or no fake QR at $sim" >&2; exit 1; }
qrterm=$(realpath "$qrterm") sim=$(realpath "$sim")  # the test runs in a folder of its own

source "$(dirname "$0")/e2e_lib.sh"
e2e_start

export LC_ALL=C
# The console's own folders (./logs/<date>-<time>) and parameter file (./qrterm-params.txt) in
# the test's folder: 21 sessions from January and one the pilot made.
cd "$work"
for day in $(seq 1 21); do mkdir -p "logs/$(printf '202501%02d-120000' "$day")"; done
mkdir -p logs/by-hand
e2e_pane "$qrterm" --sim "$sim" --sim-arg --table --sim-arg --devboard --sim-arg --core-mhz --sim-arg 16 --no-joystick
wait_for 'LINK up' 10 "start"
session=$(ls -d logs/2*-* | sort | tail -1)
log=$work/$session/console.log
ln -s "$log" logs/console.log  # where e2e_lib.sh's fail looks for it
grep -q 'removed the 2 oldest log folders: the newest 20 are kept' "$log" || fail "no word of the folders removed"
[[ $(ls -d logs/2*-* | wc -l) == 20 && -d logs/by-hand && ! -d logs/20250101-120000 && ! -d logs/20250102-120000 ]] ||
  fail "log folders left: $(ls logs | tr '\n' ' ')"
echo "e2e: ok: log folders kept to 20, the oldest removed, by-hand kept"

# The devboard: its core's load at its clock on the CPU row; b's figures are instructions.
wait_for 'cpu 42\.0 %  loop 612 us  misses 0 at 16 MHz' 3 "the CPU row: the devboard's core at 16 MHz"
keys b
wait_for 'at 16 MHz: the tick 171 us mean, 501 us at most, of 1000 us' 3 "b: the whole tick at the core's clock"
grep -q 'QR task   instr\.: mean    max overruns  (RV32 instructions: the devboard in the simulator)' "$log" ||
  fail "b: the figures are not labelled RV32 instructions"
if grep -q "host's ns" "$log"; then fail "the devboard's instructions called the host's ns"; fi

# The help: Tab named in its title; two spaces at least between an entry and the next column.
keys h
wait_for 'keys +Tab: next screen +h or \?: close' 3 "h: the help names Tab"
wait_for 'z +lift down {2,}o +P2 rate gain up {2,}9 +orientation check' 1 "the help's columns stand apart"
keys h
keys F1
wait_for 'key F1 does nothing' 3 "F1 by its name"
keys DC
wait_for 'key Delete does nothing' 3 "Delete by its name"

# The parameter screen with no parameter file: no file column (it showed the defaults as the file).
keys Tab Tab
wait_for 'no file \./qrterm-params\.txt yet' 3 "the parameter screen says there is no file"
keys Right
wait_for '^yaw_p +305 +read back +0\.\.1000 +300 *$' 5 "yaw_p stepped: default 300, and no file value after it"

# The plot's completion: ph and Tab give phi, and the names it may still become are listed.
keys Tab Tab Tab
wait_for '^PLOT' 3 "the plot screen"
keys / p h Tab
wait_for 'Enter\): phi_$' 3 "Tab: ph completes to phi, where phi and phi_sp part"
wait_for '^phi phi_sp' 1 "the candidates listed above the prompt"
keys BSpace BSpace BSpace Enter Tab Tab Tab
wait_for 'sending +lift' 3 "back on the cockpit"

# Eight presses of i: one line for the burst, once the steps stop.
keys i i i i i i i i
wait_for 'roll_pitch_p1 = 7\.5 \(5\.5 -> 7\.5 in 8 steps\)' 3 "one line for eight steps"
[[ $(grep -c 'roll_pitch_p1 = ' "$log") == 1 ]] || fail "the steps wrote $(grep -c 'roll_pitch_p1 = ' "$log") lines"

# 0 in flight: the QR goes through panic, and the log says the pilot asked, with which key.
keys 3
wait_for 'QR calibrated' 3 "3 calibrates"
keys 2
wait_for 'MODE +manual ' 3 "2: manual"
keys a a a
keys 0
wait_for 'QR mode: panic: asked by the pilot \(key 0' 3 "0 in flight says who asked"
grep -q 'QR mode: panic: asked by the pilot (key 0, safe from flight goes through panic)' "$log" ||
  fail "the panic's line in console.log"
wait_for 'MODE +safe ' 5 "then safe"

# The exit names the change saved and its undo.
keys x
wait_for 'QRTERM ENDED' 5 "x exits"
wait_for 'roll_pitch_p1 5\.5 -> 7\.5 +undo: roll_pitch_p1 = 5\.5' 1 "the exit: the change and its undo"
grep -qx 'roll_pitch_p1 = 7.5' qrterm-params.txt || fail "the parameter file lacks roll_pitch_p1 = 7.5"
echo "e2e: passed"
