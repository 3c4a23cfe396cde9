#!/usr/bin/env bash
# One axis per unit on the plot screen (issue 36: phi in rad beside height in m on one axis
# labelled "mixed" drew the roll flat), in tmux against the fake QR, whose streams carry phi
# swinging 0.1 rad and height 0.5 m about 5 m: picked together, each has its own panel with its
# unit and a scale of its size, and the phi trace climbs and falls across its panel's rows; four
# units (the most a selection has) each have a panel at 80x24, the console's least terminal.
# A few seconds. usage: e2e_plot_units.sh QRTERM FAKE_QR
set -euo pipefail

qrterm=${1:?usage: e2e_plot_units.sh QRTERM FAKE_QR}
sim=${2:?usage: e2e_plot_units.sh QRTERM FAKE_QR}
[[ -x $qrterm && -x $sim ]] || { echo "e2e: no qrterm at $qrterm or no fake QR at $sim" >&2; exit 1; }

source "$(dirname "$0")/e2e_lib.sh"
e2e_start

export LC_ALL=C  # plain characters: '*' is phi's trace, 'o' height's
e2e_pane "$qrterm" --sim "$sim" --sim-arg --table --no-joystick --log-dir "$work/logs" --params "$work/params.txt"
wait_for 'LINK up' 10 "start"
keys Tab
wait_for 'PLOT .*table of [0-9]+ observables' 5 "Tab: the plot screen with the table"
keys /
keys -l 'phi height'
keys Enter
wait_for 'streaming' 5 "phi and height stream"
wait_for '\* phi [+-][0-9.]+ rad +o height \+[0-9.]+ m' 3 "both read out in their units"

# The plot area is lines 7-19 of the pane: the axis labels in columns 1-8, the traces from 10.
# Each panel: its top value, its unit under it, ..., its bottom value. Prints "line label" for the
# area's labels, and the lines where phi's '*' is drawn.
labels() { awk 'NR >= 7 && NR <= 19 { l = substr($0, 1, 8); gsub(/ /, "", l); if (l != "") print NR, l }'; }
phi_lines() { awk 'NR >= 7 && NR <= 19 && index(substr($0, 10), "*") { print NR }'; }
# Half a swing of phi (1 s) draws it over its panel's rows; waited for, at most 4 s.
deadline=$((SECONDS + 4))
while :; do
  shot=$(screen)
  rad=$(labels <<<"$shot" | awk '$2 == "rad" { print $1 }')
  m=$(labels <<<"$shot" | awk '$2 == "m" { print $1 }')
  [[ -n $rad && -n $m ]] || fail "no rad and m axis labels: one axis for both units?"
  ((rad < m)) || fail "the rad panel (line $rad) is not above the m panel (line $m)"
  spread=$(phi_lines <<<"$shot" | awk -v below="$m" '$1 < below - 1' | sort -u | wc -l)
  ((spread >= 4)) && break
  ((SECONDS <= deadline)) || fail "phi's trace covers $spread lines of its panel: flat"
  sleep 0.2
done
grep -q mixed <<<"$shot" && fail "an axis labelled mixed"
echo "e2e: ok: rad panel from line $((rad - 1)), m panel from line $((m - 1)); phi's trace on $spread lines"
# The numbers on each panel's axis: the angle's in tenths of a radian, the height's about 5 m.
labels <<<"$shot" | awk -v rad="$rad" -v m="$m" '
  $2 ~ /^[+-][0-9.]+$/ { v = $2 + 0; a = v < 0 ? -v : v
    if ($1 < m - 1 && a > 0.5) { print "rad panel line " $1 ": " $2; bad = 1 }
    if ($1 >= m - 1 && (v < 3 || v > 7)) { print "m panel line " $1 ": " $2; bad = 1 } ; n++ }
  END { exit bad || n < 5 }' || fail "an axis value out of its unit's range (or too few values)"
echo "e2e: ok: $(labels <<<"$shot" | awk '{ printf "%s ", $2 }')"

# Four units: four panels in the 13 lines, each with its unit.
keys /
keys -l 'climb battery'
keys Enter
wait_for '4 x 200 Hz' 3 "four traces"
wait_for 'x battery [+-][0-9.]+ V' 3 "battery streams"
units=$(screen | labels | awk '$2 !~ /^[+-]/ { printf "%s ", $2 }')
[[ $units == "rad m m/s V " ]] || fail "the axis units at 80x24: '$units', expected rad m m/s V"
echo "e2e: ok: four panels at 80x24: $units"
exit_and_check_terminal
echo "e2e: passed"
