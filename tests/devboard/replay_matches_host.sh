#!/usr/bin/env bash
# Test mode on the devboard against the host: the same recording through the same chain must give
# the same CSV, byte for byte. usage: replay_matches_host.sh HOST_QRREPLAY IN.csv REPLAY_ELF
set -euo pipefail
host_replay=$1 input=$2 replay_elf=$3
root=$(cd "$(dirname "$0")/../.." && pwd)
[[ -x $host_replay ]] || { echo "no host replay at $host_replay: build the host preset first (scripts/test does)"; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$root/scripts/devboard" --elf "$replay_elf" --replay "$input" --out "$work/devboard.csv"
"$host_replay" --replay "$input" --out "$work/host.csv"
if ! cmp "$work/devboard.csv" "$work/host.csv"; then
  diff "$work/devboard.csv" "$work/host.csv" | head -n 10
  exit 1
fi
echo "replay of $(basename "$input"): $(($(wc -l <"$work/host.csv") - 1)) ticks, $(wc -c <"$work/host.csv") bytes, identical on the devboard and the host"
