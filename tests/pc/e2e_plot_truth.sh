#!/usr/bin/env bash
# The simulator's truth on the plot screen, in tmux, flying the firmware in qrsim (issue 17: "when
# the simulator's truth channel exists, truth can be drawn over the estimate"): pick height and
# climb, take off in full control, and read from the captured pane that the true height and
# climb stand beside the estimates in the same units (m, m/s) and that the true traces are drawn
# ('.' under the estimate, plain characters: the pane runs under the C locale). Then, the
# simulator's ESCs answering bidirectional DShot (issue 18), the four engines' RPM while the panic
# lands, and 0 once the engines have stopped.
set -euo pipefail

qrterm=${1:?usage: e2e_plot_truth.sh QRTERM QRSIM}
sim=${2:?usage: e2e_plot_truth.sh QRTERM QRSIM}
[[ -x $qrterm && -x $sim ]] || { echo "e2e: no qrterm at $qrterm or no qrsim at $sim" >&2; exit 1; }

source "$(dirname "$0")/e2e_lib.sh"
e2e_start

export LC_ALL=C
e2e_pane "$qrterm" --sim "$sim" --sim-arg --esc --sim-arg dshot --no-joystick --log-dir "$work/logs" \
  --params "$work/params.txt"
wait_for 'MODE +safe ' 30 "start: safe"
keys 3
wait_for 'QR calibrated' 30 "calibrated"
wait_for 'MODE +safe ' 5 "back in safe"

keys Tab
wait_for 'PLOT .*table of [0-9]+ observables' 10 "Tab: the plot screen with the whole table"
keys /
keys -l 'height climb'
keys Enter
wait_for 'streaming' 10 "height and climb stream"
wait_for '\* height [+-][0-9.]+ truth [+-][0-9.]+ m +o climb [+-][0-9.]+ truth [+-][0-9.]+ m/s' 5 \
  "the simulator's true height and climb beside the estimates, in their units"

keys 5
wait_for 'MODE +full' 3 "full control"
# Above the hover command (about 53 presses on the default vehicle): a gentle climb.
for _ in $(seq 56); do keys a; done
sleep 4
airborne=$(screen)
read -r height height_truth < <(sed -nE 's/.*\* height ([+-][0-9.]+) truth ([+-][0-9.]+) m .*/\1 \2/p' <<<"$airborne")
read -r climb climb_truth < <(sed -nE 's/.*o climb ([+-][0-9.]+) truth ([+-][0-9.]+) m\/s.*/\1 \2/p' <<<"$airborne")
awk -v h="$height" -v ht="$height_truth" -v c="$climb" -v ct="$climb_truth" \
  'function abs(x) { return x < 0 ? -x : x }
   BEGIN { exit !(ht > 0.5 && ct > 0.1 && abs(h - ht) < 1.0 && abs(c - ct) < 0.5) }' ||
  fail "climbing: height $height (truth $height_truth) m, climb $climb (truth $climb_truth) m/s: expected the truth above 0.5 m and 0.1 m/s, the estimates within 1 m and 0.5 m/s of it"
echo "e2e: ok: height $height m (truth $height_truth), climb $climb m/s (truth $climb_truth)"

# The plot area (rows 7-19 of the pane, right of the labels; e2e_plot.sh reads the same): the
# true traces' dots.
dots=$(awk 'NR >= 7 && NR <= 19 { line = substr($0, 10); n += gsub(/\./, "", line) } END { print n + 0 }' <<<"$airborne")
((dots > 0)) || fail "no true trace ('.') in the plot"
echo "e2e: ok: $dots cells of the true traces drawn"

# Down: the panic lands it at 0.5 m/s. Meanwhile the engines' RPM, from the ESCs' eRPM answers.
keys Escape
wait_for 'MODE +panic ' 3 "ESC: panic"
keys BSpace BSpace
keys /
keys -l 'rpm_front rpm_right rpm_back rpm_left'
keys Enter
wait_for '\* rpm_front \+[0-9.]+ rpm +o rpm_right \+[0-9.]+ rpm' 5 "the four engines' RPM stream"
sleep 1
landing=$(screen)
rpm=""
for engine in front right back left; do
  r=$(sed -nE "s/.* rpm_$engine \+([0-9.]+) rpm.*/\1/p" <<<"$landing" | head -1)
  # Spinning, not stopped and not wild: the default vehicle's engines read 3720 RPM each here.
  awk -v r="$r" 'BEGIN { exit !(r > 1000 && r < 40000) }' || fail "rpm_$engine '$r' while the panic lands"
  rpm+="$r "
done
echo "e2e: ok: the engines at ${rpm}RPM while the panic lands"
wait_for 'MODE +safe ' 40 "panic lands and settles in safe"
wait_for '\* rpm_front \+0\.0000 rpm +o rpm_right \+0\.0000 rpm' 3 "stopped engines read 0 RPM"
wait_for '\+ rpm_back \+0\.0000 rpm +x rpm_left \+0\.0000 rpm' 1 "all four"
exit_and_check_terminal
echo "e2e: passed"
