#!/usr/bin/env bash
# scripts/mutate leaves no mutant behind and runs alone (issue 30): on SIGTERM and SIGINT the file
# it mutated is restored at once; after a SIGKILL the next run restores it; a second run on a tree
# another is mutating refuses to start. Run on a copy of the script and the mutated file, with
# --hold (the mutant applied and held, nothing built), so the real tree is never touched.
# usage: mutate_signal_test.sh PYTHON SCRIPTS_MUTATE SOURCE_ROOT
set -euo pipefail
python=$1 script=$2 src=$3
mutant=tilt-panics-in-manual file=qr/core/safety.cpp
tmp=$(mktemp -d)
trap 'kill -9 $(jobs -p) 2>/dev/null || true; rm -rf "$tmp"' EXIT
mkdir -p "$tmp/scripts" "$tmp/$(dirname $file)"
cp "$script" "$tmp/scripts/mutate"
cp "$src/$file" "$tmp/$file"
original=$(sha256sum <"$tmp/$file")
touch -d '2020-01-02 03:04:05.123456789' "$tmp/$file"
original_time=$(stat -c %y "$tmp/$file")
fail() { echo "FAIL: $*" >&2; exit 1; }

# Starts a holding run; returns once its mutant is in the tree.
hold() {
  rm -f "$tmp/out"
  "$python" "$tmp/scripts/mutate" --only $mutant --hold 60 >"$tmp/out" 2>&1 &
  pid=$!
  for _ in $(seq 100); do grep -q '"held"' "$tmp/out" 2>/dev/null && break; sleep 0.05; done
  grep -q '"held"' "$tmp/out" || fail "the run never held its mutant: $(cat "$tmp/out")"
  [[ $(sha256sum <"$tmp/$file") != "$original" ]] || fail "the mutant is not in the file"
}

for sig in TERM INT; do
  hold
  if "$python" "$tmp/scripts/mutate" --only $mutant --hold 0 >"$tmp/second" 2>&1; then
    fail "a second run started while the first mutates the tree"
  fi
  grep -q "another scripts/mutate" "$tmp/second" || fail "the second run's refusal: $(cat "$tmp/second")"
  start=$(date +%s%N)
  kill -$sig $pid
  wait $pid || true
  ms=$(( ($(date +%s%N) - start) / 1000000 ))
  [[ $(sha256sum <"$tmp/$file") == "$original" ]] || fail "SIG$sig left the mutant in the file"
  # Its time too: a fresh one would have every other build of the tree compile it again.
  [[ $(stat -c %y "$tmp/$file") == "$original_time" ]] || fail "SIG$sig restored the file with a new time"
  (( ms < 2000 )) || fail "SIG$sig took $ms ms"
  echo "SIG$sig: restored in $ms ms"
done

hold
kill -9 $pid
wait $pid 2>/dev/null || true
[[ $(sha256sum <"$tmp/$file") != "$original" ]] || fail "SIGKILL cannot restore: the file should still be mutated here"
"$python" "$tmp/scripts/mutate" --only $mutant --hold 0 >"$tmp/next" 2>&1 || fail "the next run: $(cat "$tmp/next")"
grep -q "restored" "$tmp/next" || fail "the next run did not say it restored the file: $(cat "$tmp/next")"
[[ $(sha256sum <"$tmp/$file") == "$original" ]] || fail "the next run did not restore the file"
echo "SIGKILL: the next run restored it"
