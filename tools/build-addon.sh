#!/usr/bin/env bash
# Packs the Godot addon, addons/haptics/ as it is in the repository, into
# .build/addon/haptics-addon-<version>.zip in the Asset Library's layout (the zip's root holds
# addons/haptics/), and unpacks that zip into .build/addon/addons/haptics/ for a look.
#
# The folder's own files go in unchanged: those git tracks, or would track (not ignored).
# bin/ holds what the product builds made: the release libraries (make build-release, and
# make build-windows' release DLL), each stripped of its debug information, under both names
# the .gdextension gives for its platform. The repository's own
# bin/libhaptics.linux.template_debug.x86_64.so is the development build (make build: with
# the scripted devices the tests use) and is never packed. The release and development
# libraries are compiled from the same sources; the library's flavour only names the file.
# Usage: tools/build-addon.sh [output folder]   (needs `make build-release` first)
set -euo pipefail
cd "$(dirname "$0")/.."

ADDON_SRC=addons/haptics
OUT="${1:-.build/addon}"
VERSION="$(sed -n 's/^version="\(.*\)"$/\1/p' "$ADDON_SRC/plugin.cfg")"
RELEASE_LIB="$ADDON_SRC/bin/libhaptics.linux.template_release.x86_64.so"
SHIPPED_NAMES=(libhaptics.linux.template_debug.x86_64.so libhaptics.linux.template_release.x86_64.so)
# Windows: the same rule with make build-windows' release DLL.
WINDOWS_RELEASE_LIB="$ADDON_SRC/bin/libhaptics.windows.template_release.x86_64.dll"
WINDOWS_SHIPPED_NAMES=(libhaptics.windows.template_debug.x86_64.dll libhaptics.windows.template_release.x86_64.dll)

[[ -f "$RELEASE_LIB" ]] || { echo "build-addon: $RELEASE_LIB is missing (make build-release)" >&2; exit 1; }
# Without the Windows build (no MinGW-w64 here) the zip is Linux's only, named so, and its
# .gdextension lists Linux's libraries only: a Windows user gets Godot's "no library for
# this platform" and the door's own message, not a load error.
platforms=linux
if [[ -f "$WINDOWS_RELEASE_LIB" ]]; then
	platforms="linux windows"
else
	echo "build-addon: no $WINDOWS_RELEASE_LIB (make build-windows, which needs MinGW-w64): a Linux-only zip" >&2
fi
[[ -n "$VERSION" ]] || { echo "build-addon: no version=\"...\" line in $ADDON_SRC/plugin.cfg" >&2; exit 1; }

STAGE="$(mktemp -d "${TMPDIR:-/tmp}/haptics-addon.XXXXXX")"
trap 'rm -rf "$STAGE"' EXIT
mkdir -p "$STAGE/$ADDON_SRC/bin"
# Files inside the folder that git tracks or would track, bin/ aside.
git ls-files --cached --others --exclude-standard -- "$ADDON_SRC" | grep -v "^$ADDON_SRC/bin/" |
	while IFS= read -r file; do
		[[ -f "$file" ]] || continue # deleted in the work tree, not yet in the index
		mkdir -p "$STAGE/$(dirname "$file")"
		cp "$file" "$STAGE/$file"
	done
for name in "${SHIPPED_NAMES[@]}"; do
	cp "$RELEASE_LIB" "$STAGE/$ADDON_SRC/bin/$name"
done
# Debug information stays in the build tree.
command -v strip >/dev/null && strip --strip-debug "$STAGE/$ADDON_SRC"/bin/*.so
if [[ $platforms == *windows* ]]; then
	for name in "${WINDOWS_SHIPPED_NAMES[@]}"; do
		cp "$WINDOWS_RELEASE_LIB" "$STAGE/$ADDON_SRC/bin/$name"
	done
	x86_64-w64-mingw32-strip --strip-debug "$STAGE/$ADDON_SRC"/bin/*.dll
else
	sed -i '/^windows\./d' "$STAGE/$ADDON_SRC/haptics.gdextension"
fi
tools/check-product.sh "$STAGE/$ADDON_SRC" >/dev/null

mkdir -p "$OUT"
suffix=""
[[ $platforms == *windows* ]] || suffix=-linux-only
ZIP="$(cd "$OUT" && pwd)/haptics-addon-$VERSION$suffix.zip"
rm -f "$OUT"/haptics-addon-*.zip
(cd "$STAGE" && python3 - "$ZIP" <<'PY'
import os, sys, zipfile
with zipfile.ZipFile(sys.argv[1], "w", zipfile.ZIP_DEFLATED) as z:
    for root, dirs, files in os.walk("addons"):
        dirs.sort()
        for name in sorted(files):
            z.write(os.path.join(root, name))
PY
)
rm -rf "$OUT/addons"
python3 -c 'import sys, zipfile; zipfile.ZipFile(sys.argv[1]).extractall(sys.argv[2])' "$ZIP" "$OUT"
echo "addon: $ZIP ($(du -h "$ZIP" | cut -f1); $platforms), unpacked in $OUT/addons/haptics"
