#!/usr/bin/env bash
# The addon as a user installs it, in a game we did not build it into: a small gravity
# platformer (tests/addon/game/: a CharacterBody2D reading Input.get_axis on a TileMapLayer
# floor next to a tile wall) is copied to a temporary folder, the addon zip is unpacked into
# it, the addon README's command without the editor is run verbatim (the game has no .godot
# folder, as a fresh clone of a game has none), the project is
# imported once, then run headless: the game itself asserts a steady push away from the wall
# on every physics frame, an impact on hitting it, the wall no longer a contact once walked
# away from, and the project's servo spin (tests/addon/game/main.gd); the editor lists that
# setting with its range. Any error output fails the test. Before that, the zip holds the
# Linux and Windows libraries; after it, the plugin's static parts:
# its haptics/input/* settings and the extension list. The temporary folder is removed, also
# on failure.
# Usage: tools/test-addon.sh   (after tools/build-addon.sh)
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT="$PWD"
ZIP="$(ls .build/addon/haptics-addon-*.zip 2>/dev/null | head -n 1)"
[[ -n "$ZIP" ]] || { echo "test-addon: no addon zip in .build/addon (make addon)" >&2; exit 1; }

GAME="$(mktemp -d "${TMPDIR:-/tmp}/haptics-addon-test.XXXXXX")"
SHIM="$(mktemp -d "${TMPDIR:-/tmp}/haptics-addon-godot.XXXXXX")"
trap 'rm -rf "$GAME" "$SHIM"' EXIT

cp -r tests/addon/game/. "$GAME/"
rm -f "$GAME/.gdignore"
mv "$GAME/project.godot.in" "$GAME/project.godot"
python3 -c 'import sys, zipfile; zipfile.ZipFile(sys.argv[1]).extractall(sys.argv[2])' "$ZIP" "$GAME"

# Every library the .gdextension lists is in the zip: Linux's and Windows' (the Windows ones
# importing only Windows' own DLLs), or Linux's alone in a Linux-only zip.
mapfile -t listed < <(sed -nE 's/^[a-z]+\.[a-z_.0-9]+ = "([^"]+)"$/\1/p' "$GAME/addons/haptics/haptics.gdextension")
wanted=4
[[ $ZIP != *-linux-only.zip ]] || wanted=2
((${#listed[@]} == wanted)) || { echo "test-addon: the .gdextension lists ${#listed[@]} libraries, not $wanted" >&2; exit 1; }
for library in "${listed[@]}"; do
  [[ -s "$GAME/addons/haptics/$library" ]] || { echo "test-addon: the zip lacks addons/haptics/$library" >&2; exit 1; }
  [[ $library != *.dll ]] || tools/windows/check-imports.sh "$GAME/addons/haptics/$library" >/dev/null
done

# The README's command without the editor, verbatim from the addon's README, run in the
# game's folder with `godot` this machine's engine. The game has no .godot folder, as a
# fresh clone has none.
[[ ! -e "$GAME/.godot" ]] || { echo "test-addon: the test game comes with a .godot folder" >&2; exit 1; }
install_command="$(awk '/^Without the editor/ {f = 1} f && /^```sh/ {b = 1; next} b && /^```/ {exit} b' \
	addons/haptics/README.md)"
[[ "$install_command" == godot* ]] ||
	{ echo "test-addon: no install command in addons/haptics/README.md" >&2; exit 1; }
# The shim leaves PATH as it was: tools/godot takes a `godot` on PATH if there is one.
printf '#!/usr/bin/env bash\nPATH=%q exec %q "$@"\n' "$PATH" "$ROOT/tools/godot" >"$SHIM/godot"
chmod +x "$SHIM/godot"
if ! (cd "$GAME" && PATH="$SHIM:$PATH" bash -euo pipefail -c "$install_command") >"$GAME/.install.log" 2>&1; then
	echo "test-addon: the README's install command failed: $install_command" >&2
	sed 's/^/    /' "$GAME/.install.log" >&2
	exit 1
fi
grep -qx 'Haptics="\*res://addons/haptics/door/haptics.gd"' "$GAME/project.godot" &&
	grep -qx 'enabled=PackedStringArray("res://addons/haptics/plugin.cfg")' "$GAME/project.godot" &&
	grep -qx 'res://addons/haptics/haptics.gdextension' "$GAME/.godot/extension_list.cfg" ||
	{ echo "test-addon: the install command left project.godot or the extension list without the addon" >&2; exit 1; }
echo "test-addon: the README's command installed the addon: $install_command"

fail() {
	echo "test-addon: $1 (log below)" >&2
	sed 's/^/    /' "$2" >&2
	exit 1
}
errors() { grep -E '^(ERROR|SCRIPT ERROR|WARNING|USER ERROR|USER WARNING)' "$1" || true; }

import_log="$GAME/.import.log"
set +e
"$ROOT/tools/godot" --headless --path "$GAME" --import >"$import_log" 2>&1
rc=$?
set -e
[[ $rc -eq 0 ]] || fail "the first import exited $rc" "$import_log"
[[ -z "$(errors "$import_log")" ]] || fail "the import printed errors" "$import_log"
echo "test-addon: imported once, exit 0, no errors"

run_log="$GAME/.run.log"
set +e
timeout 120 "$ROOT/tools/godot" --headless --path "$GAME" >"$run_log" 2>&1
rc=$?
set -e
[[ $rc -eq 0 ]] || fail "the game exited $rc" "$run_log"
[[ -z "$(errors "$run_log")" ]] || fail "the game printed errors" "$run_log"
grep -E '^(impact|addon game):' "$run_log" | sed 's/^/test-addon: /'

# What the plugin does in the editor: the Project Settings dialog lists the servo's spin with
# its range. A second plugin, enabled after it, prints what the editor holds.
mkdir -p "$GAME/addons/spin_check"
printf '[plugin]\n\nname="spin_check"\ndescription=""\nauthor=""\nversion="1"\nscript="plugin.gd"\n' \
	>"$GAME/addons/spin_check/plugin.cfg"
cat >"$GAME/addons/spin_check/plugin.gd" <<'GD'
@tool
extends EditorPlugin


func _ready() -> void:
	for property: Dictionary in ProjectSettings.get_property_list():
		if property["name"] == "haptics/servo/spin_us":
			print("spin setting: range %s" % property["hint_string"])
GD
sed -i 's#^enabled=PackedStringArray("res://addons/haptics/plugin.cfg")$#enabled=PackedStringArray("res://addons/haptics/plugin.cfg", "res://addons/spin_check/plugin.cfg")#' \
	"$GAME/project.godot"
editor_log="$GAME/.editor.log"
set +e
timeout 120 "$ROOT/tools/godot" --headless --editor --path "$GAME" --quit-after 300 >"$editor_log" 2>&1
set -e
[[ -z "$(errors "$editor_log")" ]] || fail "the editor printed errors" "$editor_log"
grep -q '^spin setting: range -1,2000,1,' "$editor_log" ||
	fail "the editor does not list haptics/servo/spin_us with its range" "$editor_log"
echo "test-addon: the editor lists haptics/servo/spin_us ($(grep -m1 '^spin setting' "$editor_log"))"

# What the plugin does with the haptics/input/* settings when the editor loads it and when it
# is disabled: this game's feed_actions, and no hand_actions (as if never set).
cat >"$GAME/settings_check.gd" <<'GD'
extends SceneTree

const HAND := "haptics/input/hand_actions"
const FEED := "haptics/input/feed_actions"


func _init() -> void:
	var plugin: Script = load("res://addons/haptics/editor/plugin.gd")
	var haptics: Script = load("res://addons/haptics/door/haptics.gd")
	var own: PackedStringArray = ProjectSettings.get_setting(FEED)
	ProjectSettings.set_setting(HAND, null)
	var failures: PackedStringArray = []
	plugin.call(&"register_settings", haptics)
	if ProjectSettings.get_setting(HAND) != PackedStringArray(haptics.DEFAULT_HAND_ACTIONS):
		failures.append("hand_actions not added at its default")
	if ProjectSettings.get_setting(FEED) != own:
		failures.append("the project's feed_actions not kept")
	if ProjectSettings.property_get_revert(FEED) != PackedStringArray():
		failures.append("feed_actions does not revert to none")
	plugin.call(&"unregister_settings", haptics)
	if ProjectSettings.has_setting(HAND):
		failures.append("hand_actions, at its default, not removed")
	if ProjectSettings.get_setting(FEED) != own:
		failures.append("the project's feed_actions not kept on disabling")
	for failure: String in failures:
		printerr(failure)
	quit(1 if not failures.is_empty() else 0)
GD
settings_log="$GAME/.settings.log"
timeout 60 "$ROOT/tools/godot" --headless --path "$GAME" -s res://settings_check.gd >"$settings_log" 2>&1 ||
	fail "the plugin's settings registration" "$settings_log"
# (The autoload starting without hand_actions warns that this game lacks the default ones.)
! grep -qE '^(ERROR|SCRIPT ERROR)' "$settings_log" || fail "the settings check printed errors" "$settings_log"
echo "test-addon: the plugin lists haptics/input/* at their defaults, keeping the project's values"

# What the plugin does on enable: list the extension once, keeping what else is listed.
echo "res://elsewhere/other.gdextension" >"$GAME/.godot/extension_list.cfg"
cat >"$GAME/list_check.gd" <<'GD'
extends SceneTree


func _init() -> void:
	var plugin: Script = load("res://addons/haptics/editor/plugin.gd")
	for i: int in 2:
		if not plugin.call(&"list_extension", "res://addons/haptics/haptics.gdextension"):
			printerr("list_extension failed")
	quit()
GD
"$ROOT/tools/godot" --headless --path "$GAME" -s res://list_check.gd >/dev/null 2>&1 || true
expected=$'res://elsewhere/other.gdextension\nres://addons/haptics/haptics.gdextension'
[[ "$(cat "$GAME/.godot/extension_list.cfg")" == "$expected" ]] ||
	{ echo "test-addon: the plugin's list_extension wrote:" >&2; cat "$GAME/.godot/extension_list.cfg" >&2; exit 1; }
echo "test-addon: the plugin lists the extension once, keeping the others"
echo "test-addon: passed ($(du -h "$ZIP" | cut -f1) zip)"
