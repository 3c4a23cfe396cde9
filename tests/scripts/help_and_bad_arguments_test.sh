#!/usr/bin/env bash
# Every program in scripts/ answers --help with its usage (status 0), and a bad argument with a
# line that says what is wrong (a non-zero status, nothing built or run first). scripts/lint
# --help once failed, and scripts/recording with one argument printed its usage without saying
# what was missing.
set -uo pipefail
root=${1:?usage: help_and_bad_arguments_test.sh ROOT}
failed=0
fail() { echo "FAILED: $*" >&2; failed=1; }

for script in "$root"/scripts/*; do
  name=scripts/$(basename "$script")
  out=$(timeout 20 "$script" --help 2>&1); status=$?
  [[ $status == 0 ]] || fail "$name --help: status $status: $out"
  grep -qi 'usage' <<<"$out" || fail "$name --help says no usage: ${out:0:200}"
  # scripts/run hands options it does not know to qrterm, which judges them once it is built.
  [[ $name == scripts/run ]] && continue
  out=$(timeout 20 "$script" --no-such-option 2>&1); status=$?
  [[ $status != 0 && $status != 124 ]] || fail "$name --no-such-option: status $status"
  grep -Eqi 'unknown|unrecognized|required|no options|only' <<<"$out" ||
    fail "$name --no-such-option does not say what is wrong: ${out:0:300}"
done

out=$("$root/scripts/recording" in.csv 2>&1); status=$?
[[ $status == 2 && $out == *"missing OUT.rec"* ]] || fail "scripts/recording with one argument: status $status: $out"

[[ $failed == 0 ]] && echo "every script has --help and names a bad argument"
exit $failed
