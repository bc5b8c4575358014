#!/usr/bin/env bash
# The rigid-body trial: Godot's demo 2d/physics_platformer (its Godot 4 version; a checkout
# you give, nothing is downloaded) with this repository's haptics addon installed the
# README's way, run headless under a scripted input (physics_platformer_driver.gd): prints a
# table of landings and wall hits (from the physics server) against the impacts the probe
# sent, the peak impact force, the enemy on the head felt as weight, doubled surfaces, the
# seesaw plank taken for a load, and the lift ride's lost floors.
#
# Usage: tools/trials/physics_platformer.sh DEMO_DIR [--addon-rev REV]
#   DEMO_DIR      a copy of godot-demo-projects/2d/physics_platformer
#   --addon-rev   install the addon's scripts as they were at REV (e.g. 519d04f) instead of
#                 the worktree's; the native library is always the worktree's bin/ (make import)
# The copy goes to .build/trial/physics_platformer-<rev|worktree>/ (rebuilt each run); the
# run's log is trial.log there.
set -euo pipefail
cd "$(dirname "$0")/../.."
ROOT="$PWD"

usage() { sed -n '9,15p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }
source tools/trials/trial-copy.sh
trial_args "$@"
[[ -f "$DEMO/project.godot" && -f "$DEMO/player/player.gd" && -f "$DEMO/stage.tscn" ]] ||
	{ echo "trial: $DEMO is not the physics_platformer demo (project.godot, player/player.gd, stage.tscn)" >&2; exit 2; }
trial_copy physics_platformer tools/trials/physics_platformer_driver.gd
# The addon README's install without the editor: the autoload, the plugin, the extension
# listed before the first import; the device's hand is fed into the demo's walk actions.
cat >>"$DEST/project.godot" <<'CFG'

[autoload]

Haptics="*res://addons/haptics/door/haptics.gd"

[editor_plugins]

enabled=PackedStringArray("res://addons/haptics/plugin.cfg")

[haptics]

input/feed_actions=PackedStringArray("move_left", "move_right", "", "")
input/hand_actions=PackedStringArray()
CFG
mkdir -p "$DEST/.godot"
echo "res://addons/haptics/haptics.gdextension" >"$DEST/.godot/extension_list.cfg"

trial_run "TRIAL|HapticProbe"
