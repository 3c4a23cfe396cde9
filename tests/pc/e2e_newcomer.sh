#!/usr/bin/env bash
# What a newcomer tripped over (issue 17), tried as one would, against the firmware in qrsim:
#   a port that cannot be opened leaves no empty log folder; a line speed no port takes and a
#   folder given as --params exit 2;
#   before calibration the QR row says what to do first and the attitude reads "not valid";
#   PgUp raises the lift ten steps at a time; in flight at 80x24 the help overlay leaves mode,
#   link and engines in sight; v (the simulator's reset) is refused while the engines run and
#   sets the QR upright after; 0 in flight says safe comes through panic; a gain moved by a key is announced at exit, and a normal exit in
#   safe is confirmed by the QR (no LINK LOST: the simulator lets its last bytes through);
#   scripts/plot draws the session's telemetry.csv and refuses bad input without a traceback.
#
# usage: e2e_newcomer.sh QRTERM QRSIM
set -euo pipefail

qrterm=${1:?usage: e2e_newcomer.sh QRTERM QRSIM}
sim=${2:?usage: e2e_newcomer.sh QRTERM QRSIM}
[[ -x $qrterm && -x $sim ]] || { echo "e2e: no qrterm at $qrterm or no qrsim at $sim" >&2; exit 1; }

source "$(dirname "$0")/e2e_lib.sh"
e2e_start

# Runs qrterm to its end in the pane; leaves its exit status in $status and what it printed in
# $printed.
run_to_end() {
  e2e_pane "$qrterm" "$@"
  wait_for 'QRTERM ENDED' 10 "qrterm $* ends"
  status=$(cat "$work/status")
  printed=$(screen)
  "${tmux[@]}" kill-session -t e2e
}

# 1. Starts that fail.
run_to_end --port "$work/no-such-tty" --no-joystick --log-dir "$work/failed-logs" --params "$work/params.txt"
[[ $status == 1 ]] || fail "a port that cannot be opened: status $status, not 1"
[[ ! -e $work/failed-logs ]] || fail "a failed start left the log folder $work/failed-logs"
echo "e2e: ok: a failed port start exits 1 and leaves no log folder"
run_to_end --baud 1234 --port "$work/no-such-tty" --no-joystick --log-dir "$work/failed-logs"
[[ $status == 2 ]] || fail "--baud 1234: status $status, not 2 (docs/console.md)"
echo "e2e: ok: --baud 1234 exits 2"
mkdir "$work/a-folder"
run_to_end --params "$work/a-folder" --sim "$sim" --no-joystick --log-dir "$work/failed-logs"
[[ $status == 2 ]] || fail "a folder as --params: status $status, not 2"
[[ $printed == *"a-folder is a folder: --params names a file"* ]] || fail "a folder as --params: $printed"
[[ ! -e $work/failed-logs ]] || fail "a refused --params left the log folder"
echo "e2e: ok: a folder as --params exits 2"

# 2. The first screen: what to do first, and no attitude that looks like one.
e2e_pane "$qrterm" --sim "$sim" --no-joystick --log-dir "$work/logs" --params "$work/params.txt"
wait_for 'MODE +safe ' 30 "start: safe"
wait_for 'not calibrated: calibrate \(3\), keep it still, then choose a mode' 5 "the QR row says what to do first"
wait_for 'roll +not valid +not valid' 5 "the attitude before calibration reads not valid"
keys 3
wait_for 'QR calibrated' 30 "calibrated"
wait_for 'MODE +safe ' 5 "back in safe"
wait_for 'roll +[-+][0-9]+\.[0-9]+ +[-+][0-9]+\.[0-9]' 5 "after calibration the attitude is shown"
if screen | grep -q 'not calibrated'; then fail "the hint stays after calibration"; fi

# 3. Manual, the lift in coarse steps, the help overlay in flight.
keys 2
wait_for 'MODE +manual ' 3 "2 enters manual"
keys PPage PPage PPage
wait_for 'sending +lift +300 ' 3 "three PgUp give lift 300"
keys h
wait_for 'keys +Tab: next screen +h or \?: close' 3 "h shows the help"
pane=$(screen)
for pattern in 'MODE +manual ' 'LINK +up' '^front +[0-9]+ ' '^right +[0-9]+ ' '^back +[0-9]+ ' '^left +[0-9]+ ' 'PgUp +lift up x10' 'v +sim: set upright'; do
  grep -Eq -- "$pattern" <<<"$pane" || fail "with the help shown at 80x24, /$pattern/ is not on the screen"
done
echo "e2e: ok: the help overlay leaves mode, link and engines in sight"
keys h

# 4. The simulator's reset: refused with the engines running, done in safe. 0 in flight says that
#    safe comes through panic.
keys v
wait_for 'sim: error reset: the engines are running' 3 "v refused while the engines run"
keys 0
wait_for 'from flight through panic' 3 "0 in flight says safe goes through panic"
wait_for 'MODE +panic ' 3 "0 in flight: panic first"
wait_for 'MODE +safe ' 20 "panic settles in safe"
keys v
wait_for 'sim: the QR stands upright' 3 "v sets the QR upright"
wait_for 'truth roll [-+]0\.[0-9] pitch [-+]0\.[0-9]' 3 "the truth says level"

# 5. A gain key, then x in safe: the exit confirmed, the changed gain announced.
keys i
wait_for 'roll_pitch_p1 = 5.75' 3 "i raises P1"
keys x
wait_for 'QRTERM ENDED' 5 "x exits"
[[ $(cat "$work/status") == 0 ]] || fail "qrterm ended with status $(cat "$work/status")"
log=$work/logs/console.log
grep -q 'the QR confirmed the exit' "$log" || fail "the exit in safe was not confirmed"
if grep -Eq 'LINK LOST|exit not confirmed' "$log"; then fail "a normal exit in safe logged a lost link"; fi
echo "e2e: ok: the exit in safe is confirmed, no LINK LOST"
wait_for 'parameters changed in this session, saved to' 2 "the changed gain is announced at exit"
wait_for 'roll_pitch_p1 5.5 -> 5.75' 2 "naming the gain and its change"

# 6. scripts/plot on the file every flight writes (its early rows have empty fields), and clear
#    errors, not tracebacks, for a binary file and an --out in a missing folder.
plot=$(cd "$(dirname "$0")/../.." && pwd)/scripts/plot
"$plot" "$work/logs/telemetry.csv" --out "$work/telemetry.png" || fail "scripts/plot cannot draw telemetry.csv"
[[ $(head -c 4 "$work/telemetry.png" | od -An -tx1 | tr -d ' ') == 89504e47 ]] || fail "telemetry.png is not a PNG"
head -c 4000 /dev/urandom >"$work/binary.csv"
set +e
message=$("$plot" "$work/binary.csv" --out "$work/binary.png" 2>&1); plot_status=$?
set -e
[[ $plot_status == 1 && $message == *"not a CSV text file"* && $message != *Traceback* ]] ||
  fail "a binary CSV: status $plot_status, $message"
set +e
message=$("$plot" "$work/logs/telemetry.csv" --out "$work/no-such-folder/t.png" 2>&1); plot_status=$?
set -e
[[ $plot_status == 2 && $message == *"does not exist"* && $message != *Traceback* ]] ||
  fail "--out in a missing folder: status $plot_status, $message"
echo "e2e: ok: scripts/plot draws telemetry.csv and says what is wrong with bad input"
echo "e2e: passed"
