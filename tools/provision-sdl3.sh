#!/usr/bin/env bash
# Provisions SDL 3's headers and CMake package from Debian's `testing` suite (libsdl3-dev and
# the libsdl3-0 its CMake targets name) into .build/deps/sdl3/root (ignored), with a private
# apt state as tools/provision-engine.sh does: Debian 12 has no SDL 3, and the system's apt
# configuration is never read or written. Only those two packages are downloaded (not what they
# depend on): the build needs SDL's headers alone, because the SDL3 backend loads libSDL3.so.0
# when the game runs (gdextension/src/devices/sdl/sdl_library.h), from the exported game's
# runtime/lib/ where Debian's Godot template already needs it (tools/bundle-runtime.sh).
#
# The version is pinned (SDL3_DEBIAN_VERSION below, the one Debian's Godot in .engine was built
# with when this was written); when testing no longer carries it, testing's current version is
# taken and the script says so. A finished root is reused at no cost.
#
# Usage: tools/provision-sdl3.sh [DIR]    (default .build/deps/sdl3); prints the version on
# its last line. CMake finds the package there by itself (gdextension/CMakeLists.txt).
set -euo pipefail
project=$(cd "$(dirname "$0")/.." && pwd)
SDL3_DEBIAN_VERSION=3.4.18+ds-1
dir=$(realpath -m "${1:-"$project/.build/deps/sdl3"}")
root=$dir/root
stamp=$dir/.provisioned
die() { echo "provision-sdl3: $*" >&2; exit 1; }

if [[ -f $stamp && -f $root/usr/include/SDL3/SDL_haptic.h ]]; then
  cat "$stamp"
  exit 0
fi
command -v apt-get >/dev/null && command -v dpkg-deb >/dev/null ||
  die "needs apt-get and dpkg-deb (Debian or Ubuntu); elsewhere install SDL 3's development files and pass -DSDL3_DIR"
source "$project/tools/apt-private.sh"
rm -rf "$dir"
mkdir -p "$dir/debs" "$root"
apt_private_init "$dir/apt" testing || die "no Debian archive keyring"
apt_opts "$dir/apt/cache"
apt-get "${opts[@]}" -qq update || die "cannot read Debian testing's package index"
version=$SDL3_DEBIAN_VERSION
if ! (cd "$dir/debs" && apt-get "${opts[@]}" -qq download "libsdl3-dev=$version" "libsdl3-0=$version") 2>/dev/null; then
  version=$(apt-cache "${opts[@]}" policy libsdl3-dev | sed -nE 's/^ *Candidate: (.*)$/\1/p')
  [[ -n $version && $version != "(none)" ]] || die "Debian testing has no libsdl3-dev"
  echo "provision-sdl3: testing no longer has $SDL3_DEBIAN_VERSION; taking $version" >&2
  (cd "$dir/debs" && apt-get "${opts[@]}" -qq download "libsdl3-dev=$version" "libsdl3-0=$version") ||
    die "cannot download libsdl3-dev and libsdl3-0 $version"
fi
for deb in "$dir"/debs/*.deb; do
  dpkg-deb -x "$deb" "$root"
done
[[ -f $root/usr/include/SDL3/SDL_haptic.h ]] || die "libsdl3-dev $version holds no SDL3/SDL_haptic.h"
config=$(find "$root" -name SDL3Config.cmake -print -quit)
[[ -n $config ]] || die "libsdl3-dev $version holds no SDL3Config.cmake"
rm -rf "$dir/debs" "$dir/apt"
echo "SDL $version (Debian testing: libsdl3-dev, libsdl3-0)" | tee "$stamp"
