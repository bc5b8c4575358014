#!/usr/bin/env bash
# Checks the archive make dist wrote: it unpacks into one haptic-game/ folder holding the
# launcher, the player README with its controls, devices and permissions filled in, the udev
# rules, the licences and the same libraries as the build, and the unpacked launcher starts
# the engine (from a temporary folder outside the project, emptied environment).
set -euo pipefail
cd "$(dirname "$0")/.."
archive=.export/haptic-game-linux-x86_64.tar.gz
build=.export/linux
[[ -f $archive ]] || { echo "test-dist: $archive missing; run 'make dist'" >&2; exit 1; }
tmp=$(mktemp -d /tmp/haptic-dist-test.XXXXXX)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "test-dist: FAIL: $*"; exit 1; }

tar -C "$tmp" -xzf "$archive" || fail "the archive does not unpack"
[[ $(ls "$tmp") == haptic-game ]] || fail "the archive's top level is not one haptic-game/ folder"
game=$tmp/haptic-game
for file in haptic-game README.md 70-haptics.rules licenses/MANIFEST.txt runtime/haptic-game.loader \
  runtime/haptic-game.x86_64 runtime/haptic-game.pck runtime/lib/libc.so.6; do
  [[ -s $game/$file ]] || fail "$file is missing or empty"
done
[[ -x $game/haptic-game && -x $game/runtime/haptic-game.loader ]] || fail "the launcher lost its execute bit"
ls "$game"/runtime/libhaptics.*.so >/dev/null 2>&1 || fail "the extension library is missing"
diff <(ls "$build/runtime/lib") <(ls "$game/runtime/lib") >/dev/null ||
  fail "the archive's libraries differ from the build's"
# Every shipped library has its package's licence.
while IFS=$'\t' read -r shipped package _; do
  [[ $shipped == \#* ]] && continue
  [[ -f $game/$shipped && -s $game/licenses/$package/copyright ]] || fail "no licence for $shipped"
done <"$game/licenses/MANIFEST.txt"
for lib in "$game"/runtime/lib/* "$game"/runtime/lib-fallback/*; do
  [[ -e $lib ]] || continue
  grep -q "^${lib#"$game/"}	" "$game/licenses/MANIFEST.txt" ||
    fail "$(basename "$lib") is not in licenses/MANIFEST.txt"
done
readme=$game/README.md
grep -q "^### Side-scroller" "$readme" || fail "README: no controls"
grep -q "| pause menu | Escape" "$readme" || fail "README: the pause key is not the input map's"
grep -q "^| Device | Driver |" "$readme" || fail "README: no devices table"
grep -q "sudo cp 70-haptics.rules /etc/udev/rules.d/" "$readme" || fail "README: no udev commands"
! grep -q "@[A-Z_]*@" "$readme" || fail "README: a placeholder is left"

version=$(cd "$tmp" && env -i HOME="$tmp" PATH=/usr/bin:/bin "$game/haptic-game" --headless --version 2>&1 |
  tail -n 1) || fail "the unpacked launcher did not start the engine"
[[ $version == 4.* ]] || fail "the unpacked launcher printed '$version', not an engine version"
echo "test-dist: the archive unpacks with launcher, README, udev rules, $(ls "$game/runtime/lib" | wc -l)" \
  "libraries and their licences; the unpacked launcher runs Godot $version"
