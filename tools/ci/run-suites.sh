#!/usr/bin/env bash
# make test's driver: runs each suite named on the command line as its own make target, in
# order, stopping at the first that fails, and prints how long each took (a table at the end,
# and on a failure up to the one that failed), so a slow suite is seen where it is.
# The set-up targets make test ran first, and each suite once passed, are taken as done
# (make -o), not run again by a later suite that depends on it.
# --ahead TARGET starts TARGET (builds and downloads later suites need) niced in the
# background beside the first suites; it is over before --join-before SUITE (one that needs
# what it builds, or the first that measures time), so nothing of it competes with those.
# Its output is in .build/ahead.log; if it fails, the suites that need it make it again.
# --lanes "A..." "B..." runs, after the listed suites, two lists side by side, each in order:
# the first as usual, the second niced, so that a suite of the first that measures time (the VM
# tests' bounds) keeps a core; neither may share a make target with the other. Each lane's
# output goes to .build/lanes/lane-N.log and is printed when both are over.
#   tools/ci/run-suites.sh [--ahead TARGET --join-before SUITE] [--lanes A B] SUITE...
set -uo pipefail
cd "$(dirname "$0")/../.."
done_targets=(deps engine schema build import)
make_suite=(make --no-print-directory "${done_targets[@]/#/-o}")
ahead=""
join_before=""
lanes=()
while [[ ${1:-} == --* ]]; do
  case $1 in
    --ahead) ahead=$2 ;;
    --join-before) join_before=$2 ;;
    --lanes) lanes=("$2" "$3"); shift ;;
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
lane_pids=()
stop_ahead() {
  [[ -n $ahead_pid ]] && kill -- "-$ahead_pid" 2>/dev/null
  for pid in "${lane_pids[@]}"; do kill -- "-$pid" 2>/dev/null; done
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
  [[ $suite == "$join_before" ]] && join_ahead
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
  # A build among the suites (make export) is not made again for the ones after it.
  make_suite+=("-o$suite")
done
join_ahead
# One lane: its suites in order, stopping at the first that fails; "suite seconds status" lines
# to its times file.
run_lane() {
  local times=$1 suite start status
  shift
  for suite in "$@"; do
    start=$(date +%s)
    echo "== $suite ($(date +%H:%M:%S))"
    "${make_suite[@]}" "$suite"
    status=$?
    echo "$suite $(($(date +%s) - start)) $status" >>"$times"
    ((status == 0)) || return "$status"
  done
}
if ((${#lanes[@]})); then
  mkdir -p .build/lanes
  logs=()
  for i in 0 1; do
    read -ra suites <<<"${lanes[$i]}"
    logs+=(".build/lanes/lane-$((i + 1)).log")
    : >"${logs[$i]}.times"
    echo "== side by side: ${suites[*]} ($(date +%H:%M:%S); ${logs[$i]})"
    niceness=$((i == 0 ? 0 : 10))
    setsid nice -n "$niceness" bash -c "$(declare -f run_lane); make_suite=(${make_suite[*]}); \
      run_lane \"\$@\"" lane "${logs[$i]}.times" "${suites[@]}" >"${logs[$i]}" 2>&1 &
    lane_pids+=($!)
  done
  failed=""
  for i in 0 1; do
    wait "${lane_pids[$i]}" || failed+=" ${lanes[$i]%% *}"
  done
  lane_pids=()
  for i in 0 1; do
    cat "${logs[$i]}"
    while read -r suite took status; do
      names+=("$suite (lane $((i + 1)))")
      seconds+=("$took")
      ((status == 0)) || echo "make test: $suite failed (exit $status)" >&2
    done <"${logs[$i]}.times"
  done
  if [[ -n $failed ]]; then
    report
    exit 1
  fi
fi
report
