#!/usr/bin/env bash
# make test's driver: runs each suite named on the command line as its own make target, in
# order, stopping at the first that fails, and prints how long each took (a table at the end,
# and on a failure up to the one that failed), so a slow suite is seen where it is.
# The set-up targets make test ran first are taken as done (make -o), not run again per suite.
#   tools/ci/run-suites.sh SUITE...
set -uo pipefail
cd "$(dirname "$0")/../.."
done_targets=(deps engine schema build import)
names=()
seconds=()
start_all=$(date +%s)
report() {
  echo "make test: seconds per suite"
  for i in "${!names[@]}"; do
    printf '  %-20s %6d s\n' "${names[$i]}" "${seconds[$i]}"
  done
  printf '  %-20s %6d s\n' "all" "$(($(date +%s) - start_all))"
}
for suite in "$@"; do
  start=$(date +%s)
  echo "== $suite ($(date +%H:%M:%S))"
  make --no-print-directory "${done_targets[@]/#/-o}" "$suite"
  status=$?
  names+=("$suite")
  seconds+=($(($(date +%s) - start)))
  if ((status != 0)); then
    report
    echo "make test: $suite failed (exit $status)" >&2
    exit "$status"
  fi
done
report
