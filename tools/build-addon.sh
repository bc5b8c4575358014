#!/usr/bin/env bash
# Assembles the Godot addon from the sources where they live (scripts/haptics/,
# scenes/haptics/, assets/materials/, the built libraries) into .build/addon/addons/haptics/
# and packs it as .build/addon/haptics-addon-<version>.zip in the Asset Library's layout
# (the zip's root holds addons/haptics/). The folder is assembled outside the project tree
# on purpose: inside it, its global classes would clash with the game's own.
# Usage: tools/build-addon.sh [output folder]   (needs `make build build-release` first)
set -euo pipefail
cd "$(dirname "$0")/.."

OUT="${1:-.build/addon}"
ADDON="$OUT/addons/haptics"
RES="res://addons/haptics"
VERSION="$(sed -n 's/.*EXTENSION_VERSION = "\(.*\)";/\1/p' gdextension/src/godot/version.h)"
LIBS=(gdextension/bin/libhaptics.linux.template_debug.x86_64.so
	gdextension/bin/libhaptics.linux.template_release.x86_64.so)
SCRIPTS=(haptics.gd haptics_device.gd haptics_servo.gd haptics_pong.gd haptic_probe.gd
	haptic_material.gd addon/plugin.gd addon/haptic_water.gd)

for lib in "${LIBS[@]}"; do
	[[ -f "$lib" ]] || { echo "build-addon: $lib is missing (make build build-release)" >&2; exit 1; }
done
[[ -n "$VERSION" ]] || { echo "build-addon: no version in gdextension/src/godot/version.h" >&2; exit 1; }

rm -rf "$ADDON"
mkdir -p "$ADDON/bin" "$ADDON/materials" "$ADDON/icons"

# Where each source lands in the addon; resources refer to each other by uid, with the
# addon's own path as the fallback (rewritten here from the game's paths).
rewrite() {
	sed -e "s#res://scripts/haptics/addon/#$RES/#g" -e "s#res://scripts/haptics/#$RES/#g" \
		-e "s#res://scenes/haptics/#$RES/#g" -e "s#res://assets/materials/#$RES/materials/#g" "$1"
}
for script in "${SCRIPTS[@]}"; do
	name="$(basename "$script")"
	[[ -f "scripts/haptics/$script.uid" ]] || {
		echo "build-addon: scripts/haptics/$script.uid is missing (import the project)" >&2; exit 1; }
	rewrite "scripts/haptics/$script" >"$ADDON/$name"
	cp "scripts/haptics/$script.uid" "$ADDON/$name.uid"
done
rewrite scenes/haptics/haptic_probe.tscn >"$ADDON/haptic_probe.tscn"
for material in assets/materials/*.tres; do
	rewrite "$material" >"$ADDON/materials/$(basename "$material")"
done
cp scripts/haptics/addon/icons/*.svg "$ADDON/icons/"
sed "s/@VERSION@/$VERSION/" scripts/haptics/addon/plugin.cfg >"$ADDON/plugin.cfg"
cp scripts/haptics/addon/README.md "$ADDON/README.md"
cp LICENSE "$ADDON/LICENSE"
cp "${LIBS[@]}" "$ADDON/bin/"
# Debug information stays in the build tree (it is most of the debug library's size).
command -v strip >/dev/null && strip --strip-debug "$ADDON"/bin/*.so
# Library paths relative to the .gdextension file: the folder works wherever it is placed.
sed -e '/^\(windows\|macos\)\./d' gdextension/haptics.gdextension >"$ADDON/haptics.gdextension"

# A leftover reference to the game's own folders would break in another project.
if grep -rn "res://\(scripts\|scenes\|assets\)/" "$ADDON" --include='*.gd' --include='*.tscn' \
	--include='*.tres' --include='*.gdextension'; then
	echo "build-addon: the addon still refers to the game's files (above)" >&2
	exit 1
fi

ZIP="$OUT/haptics-addon-$VERSION.zip"
rm -f "$ZIP"
(cd "$OUT" && python3 - "haptics-addon-$VERSION.zip" <<'PY'
import os, sys, zipfile
with zipfile.ZipFile(sys.argv[1], "w", zipfile.ZIP_DEFLATED) as z:
    for root, dirs, files in os.walk("addons"):
        dirs.sort()
        for name in sorted(files):
            z.write(os.path.join(root, name))
PY
)
echo "addon: $ADDON ($(du -sh "$ADDON" | cut -f1)), $ZIP ($(du -h "$ZIP" | cut -f1))"
