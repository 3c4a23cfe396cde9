#!/usr/bin/env bash
# The plot screen's figures (issue 17), on the firmware in qrsim: four traces at 200 Hz (phi,
# theta, psi and time_ms, the QR's clock) for ten seconds. Prints one JSON line:
#   cpu: qrterm's CPU time over those seconds (utime + stime from /proc), in % of one core;
#   latency: from the QR's tick that took a sample to the first screen showing it, median and
#   90th percentile, measured by qrterm itself (time_ms against qrsim's clock from its truth
#   channel; Cockpit::latency_summary).
# Figures, not assertions: the targets (<= 5 %, <= 50 ms) are judged by whoever reads them. The
# host preset builds qrterm with ASan and UBSan, which the CPU figure then includes ("build").
set -euo pipefail

qrterm=${1:?usage: bench_plot.sh QRTERM QRSIM [SECONDS]}
sim=${2:?usage: bench_plot.sh QRTERM QRSIM [SECONDS]}
seconds=${3:-10}
[[ -x $qrterm && -x $sim ]] || { echo "bench: no qrterm at $qrterm or no qrsim at $sim" >&2; exit 1; }

source "$(dirname "$0")/e2e_lib.sh"
e2e_start

export LC_ALL=C.UTF-8  # braille cells: the screen as a pilot would have it
e2e_pane "$qrterm" --sim "$sim" --no-joystick --log-dir "$work/logs" --params "$work/params.txt"
wait_for 'MODE +safe ' 30 "start: safe"
keys Tab
wait_for 'PLOT .*table of [0-9]+ observables' 10 "the plot screen"
keys /
keys -l 'phi theta psi time_ms'
keys Enter
wait_for '4 x 200 Hz' 5 "four traces at 200 Hz"
wait_for 'streaming' 10 "streaming"
sleep 2

pid=$(cat "$work/qrterm.pid")
ticks() { awk '{ print $14 + $15 }' "/proc/$pid/stat"; }
hz=$(getconf CLK_TCK)
before=$(ticks)
start=$EPOCHREALTIME
sleep "$seconds"
after=$(ticks)
elapsed=$(awk "BEGIN { print $EPOCHREALTIME - $start }")
lost=$(screen | sed -nE 's/.*lost ([0-9]+).*/\1/p' | head -1)
exit_and_check_terminal

latency=$(grep -h 'plot latency, tick to screen' "$work/logs/console.log" | tail -1)
[[ -n $latency ]] || fail "qrterm measured no latency"
median=$(sed -nE 's/.*median ([0-9]+) ms.*/\1/p' <<<"$latency")
p90=$(sed -nE 's/.*90th percentile ([0-9]+) ms.*/\1/p' <<<"$latency")
screens=$(sed -nE 's/.* over ([0-9]+) screens.*/\1/p' <<<"$latency")
samples=$(($(wc -l <"$work/logs/observables_1.csv") - 1))
cpu=$(awk "BEGIN { printf \"%.1f\", ($after - $before) / $hz / $elapsed * 100 }")
build="unsanitised"
# grep reads all of nm's output (no -q): under pipefail an early exit would fail the pipe.
if nm "$qrterm" 2>/dev/null | grep __asan_init >/dev/null; then build="ASan+UBSan"; fi
echo "{\"plot\": {\"traces\": 4, \"rate_hz\": 200, \"seconds\": $elapsed, \"console_cpu_percent_of_one_core\": $cpu, \"latency_tick_to_screen_median_ms\": $median, \"latency_p90_ms\": $p90, \"screens\": $screens, \"csv_rows\": $samples, \"samples_lost\": ${lost:-0}, \"build\": \"$build\", \"targets\": {\"cpu_percent\": 5, \"latency_median_ms\": 50}}}"
