#!/usr/bin/env bash
# A game developer's first hour with the addon, in the GUI editor (Xvfb, Compatibility
# renderer) started through tools/godot, in one editor session: a project that has never seen
# the addon (tests/editor/game/) is opened, and the test's own editor plugin
# (addons/editor_driver) unpacks the addon zip into it while the editor runs, lets the editor
# find it, enables the Haptics plugin, writes the scene's script, creates a scene with a
# HapticProbe the way the Create dialog does, saves it and plays it (F6). The played game
# checks that the hand is pushed out of the floor and quits; the editor then quits.
# Fails on a non-zero exit, a failed step, a game that did not report, or any error or
# warning line from the editor or the game. The temporary project is removed.
# Usage: tools/test-editor.sh   (after tools/build-addon.sh; the log is .build/test-editor.log)
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT="$PWD"
ZIP="$(ls .build/addon/haptics-addon-*.zip 2>/dev/null | head -n 1)"
[[ -n "$ZIP" ]] || { echo "test-editor: no addon zip in .build/addon (make addon)" >&2; exit 1; }
source tools/xvfb.sh

scratch=$(mktemp -d "${TMPDIR:-/tmp}/haptics-editor-test.XXXXXX")
wm_pid=""
cleanup() {
  [[ -n $wm_pid ]] && { kill "$wm_pid" 2>/dev/null || true; wait "$wm_pid" 2>/dev/null || true; }
  xvfb_stop
  # KEEP=1 keeps the project the editor worked on, to look at after a failure.
  if [[ ${KEEP:-} == 1 ]]; then echo "test-editor: kept $scratch" >&2; else rm -rf "$scratch"; fi
}
trap cleanup EXIT
game=$scratch/game
cp -r tests/editor/game "$game"
rm -f "$game/.gdignore"
mv "$game/project.godot.in" "$game/project.godot"
mkdir -p .build
log=.build/test-editor.log

fail() {
  echo "test-editor: FAIL: $1 (log: $log)" >&2
  grep -E '^(editor-test|probe-check):|^(ERROR|SCRIPT ERROR|WARNING|USER ERROR|USER WARNING)|Parse Error' \
    "$log" | head -n 40 >&2 || tail -n 30 "$log" >&2
  exit 1
}

xvfb_start "$scratch" || fail "no display"
# A window manager, as on a desktop: the editor floats the game it plays in a window of its own
# (game embedding), and on a bare X server that ends in BadWindow errors no desktop shows.
command -v openbox >/dev/null || fail "openbox missing (make deps installs it)"
DISPLAY=$XVFB_DISPLAY openbox >"$scratch/wm.log" 2>&1 &
wm_pid=$!
status=0
DISPLAY=$XVFB_DISPLAY HAPTICS_ADDON_ZIP="$ROOT/$ZIP" \
  HAPTICS_EDITOR_TEST_SCRIPT="$ROOT/tests/editor/probe_check.gd" \
  timeout 600 tools/godot --editor --path "$game" --rendering-driver opengl3 --audio-driver Dummy \
  >"$log" 2>&1 || status=$?
((status == 0)) || fail "the editor exited $status"
# The last step closes the window: the editor quits by itself, asking nothing.
grep -q "^editor-test: close the editor's window" "$log" || fail "the driver did not finish its steps"
grep -q '^editor-test: FAIL' "$log" && fail "a step failed"
grep -q '^probe-check: ok' "$log" || fail "the played scene did not report a push out of the floor"
# What this machine's virtual display prints, not the editor's or the addon's doing: Mesa's
# software rasteriser under Xvfb cannot set V-Sync, and a virtual display has no Vulkan surface
# (the editor probes for one even when it renders with OpenGL; the probe's own error follows).
unexplained=$(awk '
  /^WARNING: Could not set V-Sync mode, as changing V-Sync mode is not supported/ { next }
  /^ERROR: Required extension VK_KHR_surface not found/ { vulkan = 1; next }
  vulkan && /^ERROR: Condition "err != OK" is true. Returning: err/ { vulkan = 0; next }
  /^(ERROR|SCRIPT ERROR|WARNING|USER ERROR|USER WARNING)|Parse Error/ { print }
' "$log")
[[ -z $unexplained ]] || fail "error or warning lines: $unexplained"
grep -E '^(editor-test: ok|probe-check)' "$log" | sed 's/^/test-editor: /'
echo "test-editor: passed: unzip, enable, create a HapticProbe and play it (F6) in one editor session"
