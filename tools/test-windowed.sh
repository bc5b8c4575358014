#!/usr/bin/env bash
# Runs the game in a window (Xvfb, the Compatibility renderer on Mesa's software rasteriser)
# under its autopilot for a few seconds, lets it quit, and fails on a non-zero exit or on any
# report of something leaked at exit. Headless runs play no sound, so only a windowed run
# shows leaks on the way out (CleanExit, game/common/clean_exit.gd).
#
#   tools/test-windowed.sh [SECONDS]      (default 4; the log is .build/test-windowed.log)
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-4}
source tools/xvfb.sh
mkdir -p .build
log=.build/test-windowed.log
scratch=$(mktemp -d)
cleanup() {
  xvfb_stop
  rm -rf "$scratch"
}
trap cleanup EXIT
xvfb_start "$scratch" || { echo "test-windowed: no display" >&2; exit 1; }
display=$XVFB_DISPLAY

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
