#!/usr/bin/env bash
# Runs the game from a temporary copy of the project that lacks the native extension, the
# way a player without a built library would: it must start, warn once, and play without
# force feedback. Arguments go to the engine, e.g. -- --system-check, or
# res://tests/drivers/game_autopilot.tscn -- --autopilot-seconds=2 (level 1 under the autopilot).
set -euo pipefail
project=$(cd "$(dirname "$0")/.." && pwd)
copy=$(mktemp -d)
trap 'rm -rf "$copy"' EXIT
tar -C "$project" --exclude=./.git --exclude=./.engine --exclude=./.build --exclude=./.venv \
  --exclude=./.xdg --exclude=./.export --exclude=./.bench --exclude=./.godot \
  --exclude=./gdextension --exclude=./addons/haptics/bin -cf - . | tar -C "$copy" -xf -
"$project/tools/godot" --headless --path "$copy" --import >"$copy/import.log" 2>&1 ||
  { tail -n 20 "$copy/import.log"; exit 1; }
"$project/tools/godot" --headless --path "$copy" "$@"
