#!/usr/bin/env bash
# scripts/envelope end to end, cheaply: one scenario, two seeds, on the qrsim of this build (the
# real section 7 is every scenario over 30 seeds on a release build, minutes of runs, which stay
# out of CTest). It writes the part of a page between the markers and nothing else, --check
# --from the runs it saved agrees, and a changed figure or a page without markers is caught.
# usage: envelope_test.sh PYTHON3 SCRIPTS_ENVELOPE QRSIM WORK_DIR
set -euo pipefail
python=$1 script=$2 qrsim=$3 dir=$4
envelope() { "$python" "$script" "$@"; }
mkdir -p "$dir"
doc=$dir/page.md runs=$dir/runs.json
printf 'before\n<!-- envelope:begin -->\nstale\n<!-- envelope:end -->\nafter\n' >"$doc"

envelope --qrsim "$qrsim" --only disturbance --seeds 2 --jobs 1 --doc "$doc" --save "$runs"
[[ $(head -n 1 "$doc") == before && $(tail -n 1 "$doc") == after ]] || { echo "the text around the markers changed"; exit 1; }
! grep -q '^stale$' "$doc" || { echo "the old section is still there"; exit 1; }
grep -q '^Measured by `scripts/envelope --seeds 2 --only disturbance` at ' "$doc" || { echo "no provenance line"; exit 1; }
grep -Eq '^\| `disturbance` \| `recovery_s < 1` \| pass, [0-9.]+ \| [0-2]/2, worst [0-9.]+ \| [0-2]/2, worst [0-9.]+ \|$' "$doc" ||
  { echo "no row for disturbance's recovery_s band"; cat "$doc"; exit 1; }

envelope --check --from "$runs" --doc "$doc"

sed -i '0,/, worst /s//, worst 9/' "$doc"
if envelope --check --from "$runs" --doc "$doc"; then echo "--check missed a changed figure"; exit 1; fi

printf 'no markers\n' >"$doc"
status=0
envelope --check --from "$runs" --doc "$doc" || status=$?
[[ $status -eq 1 ]] || { echo "--check on a page without markers: exit $status, not 1"; exit 1; }
echo "envelope_test: ok"
