#!/usr/bin/env bash
# Packs the self-contained Linux build (.export/linux/, make export) into
# .export/haptic-game-linux-x86_64.tar.gz, one folder haptic-game/ holding the build, the
# player README (tools/dist/README.player.md, completed from the project's own sources: the
# controls from the input map, the devices table and the udev commands from docs/devices.md, the
# glibc version from the shipped one) and the udev rules. Prints the archive's size.
set -euo pipefail
cd "$(dirname "$0")/.."
build=.export/linux
archive=.export/haptic-game-linux-x86_64.tar.gz
die() { echo "dist: $*" >&2; exit 1; }
[[ -x $build/haptic-game && -d $build/runtime/lib ]] ||
  die "$build is not a self-contained build; run 'make export'"

stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
top=$stage/haptic-game
cp -a "$build" "$top"
cp tools/udev/70-haptics.rules "$top/"

tools/godot --headless --path . -s tools/dist/controls.gd >"$stage/controls.log" 2>&1 ||
  { tail -n 20 "$stage/controls.log"; die "the controls could not be read from the input map"; }
controls=$(sed -n '/^### /,$p' "$stage/controls.log")
devices=$(sed -n '/^| Device | Driver |/,/^$/p' docs/devices.md)
udev=$(awk '/^## Permissions/ { on = 1 } on && /^```/ { print; if (++fences == 2) exit; next }
  fences == 1 { print }' docs/devices.md | sed 's,tools/udev/,,')
glibc=$(readelf -V "$build/runtime/lib/libc.so.6" | grep -oE "GLIBC_[0-9.]+" | sort -uV | tail -n 1)
[[ -n $controls && -n $devices && $udev == *70-haptics.rules* && -n $glibc ]] ||
  die "docs/devices.md no longer has what the player README takes from it"
# Whole-line placeholders take a block; @GLIBC@ is replaced within lines.
controls=$controls devices=$devices udev=$udev glibc=${glibc#GLIBC_} awk '
  $0 == "@CONTROLS@" { print ENVIRON["controls"]; next }
  $0 == "@DEVICES@" { print ENVIRON["devices"]; next }
  $0 == "@UDEV@" { print ENVIRON["udev"]; next }
  { gsub(/@GLIBC@/, ENVIRON["glibc"]); print }
' tools/dist/README.player.md >"$top/README.md"
! grep -q "@[A-Z_]*@" "$top/README.md" || die "a placeholder of the player README was left unfilled"

mkdir -p "$(dirname "$archive")"
tar -C "$stage" -czf "$archive.partial" haptic-game
mv "$archive.partial" "$archive"
echo "dist: $archive: $(du -b "$archive" | cut -f1) bytes ($(du -h "$archive" | cut -f1)),"  \
  "$(du -sb "$top" | cut -f1) bytes unpacked ($(du -sh "$top" | cut -f1))," \
  "$(find "$top" -type f | wc -l) files"
