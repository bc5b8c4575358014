#!/usr/bin/env bash
# make test's driver: runs each suite named on the command line as its own make target, in
# order, stopping at the first that fails, and prints how long each took (a table at the end,
# and on a failure up to the one that failed), so a slow suite is seen where it is.
# The set-up targets make test ran first are taken as done (make -o), not run again per suite.
# --ahead TARGET starts TARGET (builds and downloads later suites need) niced in the
# background beside the first suites; it must be over before --timed-from SUITE, the first
# suite that measures time, so nothing of it competes with those. Its output is in
# .build/ahead.log; if it fails, the suites that need it make it again and say why.
#   tools/ci/run-suites.sh [--ahead TARGET --timed-from SUITE] SUITE...
set -uo pipefail
cd "$(dirname "$0")/../.."
done_targets=(deps engine schema build import)
make_suite=(make --no-print-directory "${done_targets[@]/#/-o}")
ahead=""
timed_from=""
while [[ ${1:-} == --* ]]; do
  case $1 in
    --ahead) ahead=$2 ;;
    --timed-from) timed_from=$2 ;;
    *) echo "run-suites: unknown option $1" >&2; exit 2 ;;
  esac
  shift 2
done
names=()
seconds=()
start_all=$(date +%s)
ahead_pid=""
ahead_log=.build/ahead.log
report() {
  echo "make test: seconds per suite"
  for i in "${!names[@]}"; do
    printf '  %-22s %6d s\n' "${names[$i]}" "${seconds[$i]}"
  done
  printf '  %-22s %6d s\n' "all" "$(($(date +%s) - start_all))"
}
stop_ahead() {
  [[ -n $ahead_pid ]] && kill -- "-$ahead_pid" 2>/dev/null
  return 0
}
trap stop_ahead EXIT
# Waits for the ahead job; its own row says how long it ran beside the suites.
join_ahead() {
  [[ -n $ahead_pid ]] || return 0
  local status=0
  wait "$ahead_pid" || status=$?
  ahead_pid=""
  names+=("$ahead (beside)")
  seconds+=($(($(date +%s) - ahead_start)))
  if ((status != 0)); then
    tail -n 20 "$ahead_log"
    echo "make test: $ahead failed (exit $status; $ahead_log); the suites that need it go on" >&2
  fi
}
if [[ -n $ahead ]]; then
  mkdir -p .build
  ahead_start=$(date +%s)
  echo "== $ahead, beside the suites ($(date +%H:%M:%S); $ahead_log)"
  # Its own process group, so that a failure or an interrupt stops all of it.
  setsid nice -n 19 "${make_suite[@]}" "$ahead" >"$ahead_log" 2>&1 &
  ahead_pid=$!
fi
for suite in "$@"; do
  [[ $suite == "$timed_from" ]] && join_ahead
  start=$(date +%s)
  echo "== $suite ($(date +%H:%M:%S))"
  "${make_suite[@]}" "$suite"
  status=$?
  names+=("$suite")
  seconds+=($(($(date +%s) - start)))
  if ((status != 0)); then
    report
    echo "make test: $suite failed (exit $status)" >&2
    exit "$status"
  fi
done
join_ahead
report
