#!/usr/bin/env bash
# Runs the game in a window (Xvfb, the Compatibility renderer on Mesa's software rasteriser)
# twice, lets it quit each time, and fails on a non-zero exit, an error line or any report of
# something leaked at exit: under its autopilot for a few seconds
# (tests/drivers/game_autopilot.tscn: the real main scene and level 1, steered by the test
# driver), then the product alone, its main menu under its own system check (what the
# export test runs). Headless runs play no sound, so only a windowed run shows leaks on the
# way out (CleanExit, game/common/clean_exit.gd).
#
#   tools/test-windowed.sh [SECONDS]      (default 4; the logs are .build/test-windowed*.log)
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
# What the engine prints about anything still alive at exit (--verbose adds the details).
leaks="leaked at exit|still in use at exit|Leaked instance|Resource still in use|Orphan StringName|unclaimed string names|RID allocations.*leaked"

fail() {
  echo "test-windowed: FAIL: $1 (log: $log)"
  grep -nE -A2 "$leaks|^(ERROR|SCRIPT ERROR)" "$log" | head -n 40 || tail -n 20 "$log"
  exit 1
}
# Runs the project in the window with "$@" (scene and arguments) into $log; fails on a
# non-zero exit, a leak or an error line.
run_windowed() {
  local status=0
  DISPLAY=$display timeout 180 tools/godot --verbose --path . --rendering-driver opengl3 \
    --audio-driver Dummy "$@" >"$log" 2>&1 || status=$?
  ((status == 0)) || fail "exit status $status"
  grep -qE "$leaks" "$log" && fail "leaks reported at exit"
  grep -qE "^(ERROR|SCRIPT ERROR)" "$log" && fail "errors were printed"
  return 0
}

run_windowed res://tests/drivers/game_autopilot.tscn -- --autopilot-seconds="$seconds"
grep -q "^Autopilot on" "$log" || fail "the game did not start windowed under the autopilot"
grep -q "^t= 1.0s" "$log" || fail "the autopilot did not run"
echo "test-windowed: ${seconds} s under the autopilot windowed under Xvfb ($display), quit" \
  "cleanly: exit 0, no leak reported"

log=.build/test-windowed-menu.log
run_windowed -- --system-check
grep -q "^System check: the main menu showed" "$log" || fail "the main menu did not show"
echo "test-windowed: the main menu windowed (--system-check), quit cleanly: exit 0, no leak" \
  "reported"
