#!/usr/bin/env bash
# make test-godot: the GDScript suite as N runners side by side (--shard=K/N), each with its
# own user data (HAPTICS_XDG_ROOT), output (.build/godot-shard-K.log) and JUnit file
# (.build/godot-tests-K.xml). Most of the suite waits on frames of scenes that run in real
# time, so two runners on two cores take about half as long as one.
# Prints each runner's output in turn when all are over and the summary of all; fails if any
# runner failed.
#   tools/ci/godot-shards.sh N [runner options...]
set -uo pipefail
cd "$(dirname "$0")/../.."
shards=$1
shift
mkdir -p .build
pids=()
for ((k = 1; k <= shards; k++)); do
  root=.xdg/shards/$k
  rm -rf "$root"
  HAPTICS_XDG_ROOT=$PWD/$root tools/godot --headless --path . res://tests/runner/runner.tscn -- \
    --shard="$k/$shards" --junit=".build/godot-tests-$k.xml" "$@" >".build/godot-shard-$k.log" 2>&1 &
  pids+=($!)
done
failed=0
summaries=()
for ((k = 1; k <= shards; k++)); do
  wait "${pids[$((k - 1))]}" || failed=1
  log=.build/godot-shard-$k.log
  echo "== runner $k of $shards ($log)"
  cat "$log"
  summaries+=("$(grep -E '^[0-9]+ passed, [0-9]+ failed' "$log" | tail -n 1)")
done
total() { grep -oE "[0-9]+ $1" <<<"${summaries[*]}" | awk '{n += $1} END {print n + 0}'; }
echo "all runners: $(total passed) passed, $(total failed) failed, $(total skipped) skipped"
exit "$failed"
