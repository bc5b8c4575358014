#!/usr/bin/env bash
# Runs the game in a window (Xvfb, the Compatibility renderer on Mesa's software rasteriser)
# under its autopilot for a few seconds, lets it quit, and fails on a non-zero exit or on any
# report of something leaked at exit. Headless runs play no sound, so only a windowed run
# shows leaks on the way out (CleanExit, scripts/common/clean_exit.gd).
#
#   tools/test-windowed.sh [SECONDS]      (default 4; the log is .build/test-windowed.log)
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-4}
command -v Xvfb >/dev/null || {
  echo "test-windowed: Xvfb missing (make deps installs it)" >&2
  exit 1
}
mkdir -p .build
log=.build/test-windowed.log
scratch=$(mktemp -d)
xvfb_pid=""
cleanup() {
  if [[ -n $xvfb_pid ]]; then
    kill "$xvfb_pid" 2>/dev/null || true
    wait "$xvfb_pid" 2>/dev/null || true
  fi
  rm -rf "$scratch"
}
trap cleanup EXIT

# -displayfd: Xvfb picks a free display and writes its number once it accepts clients.
Xvfb -displayfd 3 -screen 0 1280x720x24 -nolisten tcp 3>"$scratch/display" 2>"$scratch/xvfb.log" &
xvfb_pid=$!
for _ in $(seq 100); do
  [[ -s $scratch/display ]] && break
  kill -0 "$xvfb_pid" 2>/dev/null || break
  sleep 0.1
done
[[ -s $scratch/display ]] || {
  cat "$scratch/xvfb.log" >&2
  echo "test-windowed: Xvfb did not start" >&2
  exit 1
}
display=:$(head -n 1 "$scratch/display")

status=0
DISPLAY=$display timeout 180 tools/godot --verbose --path . --rendering-driver opengl3 \
  --audio-driver Dummy -- --autopilot --autopilot-seconds="$seconds" >"$log" 2>&1 || status=$?
fail() {
  echo "test-windowed: FAIL: $1 (log: $log)"
  grep -nE -A2 "$leaks|^(ERROR|SCRIPT ERROR)" "$log" | head -n 40 || tail -n 20 "$log"
  exit 1
}
# What the engine prints about anything still alive at exit (--verbose adds the details).
leaks="leaked at exit|still in use at exit|Leaked instance|Resource still in use|Orphan StringName|unclaimed string names|RID allocations.*leaked"
((status == 0)) || fail "exit status $status"
grep -q "^Autopilot on (--autopilot)" "$log" || fail "the game did not start windowed under the autopilot"
grep -q "^t= 1.0s" "$log" || fail "the autopilot did not run"
grep -qE "$leaks" "$log" && fail "leaks reported at exit"
grep -qE "^(ERROR|SCRIPT ERROR)" "$log" && fail "errors were printed"
echo "test-windowed: ${seconds} s windowed under Xvfb ($display), quit cleanly: exit 0, no leak reported"
