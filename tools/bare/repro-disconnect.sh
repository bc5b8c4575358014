#!/usr/bin/env bash
# Shows that the "Attempt to disconnect a nonexistent connection ... callable: ''" lines the
# release build prints at exit are the engine's, not the game's: a project of one script and
# no addon builds a container holding N labels, takes one out while running, connects and
# disconnects a signal of its own, then quits; it runs under the engine's release and debug
# templates (the project-local engine's). Prints, for each template, the error lines seen
# while running (one removal, the script's own disconnect) and at exit (the tree freed);
# exits 1 unless the release template alone prints them, and only for the container's
# children (3 of the engine's own connections each: size flags, minimum size, visibility).
#
#   tools/bare/repro-disconnect.sh [N]   (default 10 labels)
set -euo pipefail
cd "$(dirname "$0")/../.."
labels=${1:-10}
root=$PWD/.engine/root
loader=$root/usr/lib64/ld-linux-x86-64.so.2
[[ -e $loader ]] || loader=$root/lib64/ld-linux-x86-64.so.2
[[ -x $root/usr/bin/godot-template-release ]] ||
  { echo "repro-disconnect: no project-local engine with templates in $root (make engine)" >&2; exit 1; }
libs=$root/usr/lib/x86_64-linux-gnu:$root/usr/lib/x86_64-linux-gnu/pulseaudio
tmp=$(mktemp -d /tmp/haptic-disconnect-repro.XXXXXX)
trap 'rm -rf "$tmp"' EXIT
project=$tmp/project
mkdir "$project"
cat >"$project/project.godot" <<'CFG'
config_version=5

[application]

config/name="disconnect repro"
run/main_scene="res://repro.tscn"
CFG
cat >"$project/export_presets.cfg" <<'CFG'
[preset.0]

name="Linux"
platform="Linux"
runnable=true
export_filter="all_resources"
include_filter=""
exclude_filter=""
export_path=""

[preset.0.options]
CFG
cat >"$project/repro.tscn" <<'TSCN'
[gd_scene load_steps=2 format=3]

[ext_resource type="Script" path="res://repro.gd" id="1"]

[node name="Repro" type="Node"]
script = ExtResource("1")
TSCN
cat >"$project/repro.gd" <<'GD'
extends Node

var box := VBoxContainer.new()
var frames := 0


func _ready() -> void:
	add_child(box)
	for i in int(OS.get_cmdline_user_args()[0]):
		var label := Label.new()
		label.name = "Removed" if i == 0 else "Kept%d" % i
		box.add_child(label)


func _own() -> void:
	pass


func _process(_delta: float) -> void:
	frames += 1
	if frames == 3:
		var label: Label = box.get_node("Removed")
		box.remove_child(label)
		label.free()
		box.get_child(0).resized.connect(_own)
		box.get_child(0).resized.disconnect(_own)
		print("repro: done")
		get_tree().quit()
GD
# A release template runs only a pack: <executable>.pck beside /proc/self/exe, which is the
# loader when the loader starts the engine (as in the game's bundle).
tools/godot --headless --path "$project" --export-pack Linux "$tmp/repro.pck" >"$tmp/export.log" 2>&1 ||
  { tail -n 20 "$tmp/export.log"; echo "repro-disconnect: the pack was not made" >&2; exit 1; }
cp -L "$loader" "$tmp/repro.loader"
status=0
declare -A running=() exiting=()
for flavour in release debug; do
  log=$tmp/$flavour.log
  (cd "$tmp" && HOME=$tmp timeout 60 "$tmp/repro.loader" --library-path "$libs" \
    "$root/usr/bin/godot-template-$flavour" --headless -- "$labels" \
    >"$log" 2>&1) || { tail -n 20 "$log"; echo "repro-disconnect: the $flavour template failed" >&2; exit 1; }
  grep -q "^repro: done" "$log" || { tail -n 20 "$log"; exit 1; }
  # The engine's errors go to stderr unbuffered, our prints to a buffered stdout: the label's
  # name says when each line came (the one removed while running, the others at exit).
  pattern="^ERROR: Attempt to disconnect a nonexistent connection"
  running[$flavour]=$(grep "$pattern" "$log" | grep -c "from 'Removed:" || true)
  exiting[$flavour]=$(grep "$pattern" "$log" | grep -c "from 'Kept" || true)
  others=$(grep "^ERROR" "$log" | grep -vcE "from '(Removed|Kept)" || true)
  echo "repro-disconnect: $flavour template, $labels labels in a VBoxContainer:" \
    "${running[$flavour]} lines for the one removed while running," \
    "${exiting[$flavour]} for the rest at exit, $others other errors" \
    "($(grep -m 1 "$pattern" "$log" | cut -c 1-150 || echo none))"
  ((others == 0)) || status=1
done
# Each container child: 2 lines (its size_flags_changed and visibility_changed; the third
# connection, minimum_size_changed, is found), however it leaves; the script's own
# disconnect finds its connection.
[[ ${running[release]} == 2 && ${exiting[release]} == $((2 * (labels - 1))) ]] || status=1
[[ ${running[debug]} == 0 && ${exiting[debug]} == 0 ]] || status=1
((status == 0)) && echo "repro-disconnect: the engine's release template alone prints them, 2 per" \
  "container child removed (while running or at exit); the script's own disconnect, none"
exit "$status"
