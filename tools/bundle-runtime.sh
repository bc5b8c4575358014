#!/usr/bin/env bash
# Makes the Linux export in DIR (default .export/linux) self-contained: the release template,
# the pack and the extension move into DIR/runtime/ beside the glibc loader and every shared
# library they need (DIR/runtime/lib/), and DIR/NAME (tools/dist/launcher.sh) starts the game
# through that loader with that library path only. The GPU driver (libGL, libEGL,
# libGLX, libgbm, Vulkan and what Mesa or a vendor driver loads) is left to the system:
# it must match the kernel driver and the hardware of the machine it runs on. Those of them
# the engine links at load time (libgbm, linked by SDL) are also shipped in DIR/runtime/
# lib-fallback/, which the launcher adds only on a system that lacks them (a server, a
# container): without them the game could not start even headless.
# Licences of what is shipped go to DIR/licenses/ (one folder per Debian package, and
# MANIFEST.txt: library, package, version).
#
# Usage: tools/bundle-runtime.sh [DIR [NAME]]   (default .export/linux haptic-game)
set -euo pipefail
cd "$(dirname "$0")/.."
dir=${1:-.export/linux}
name=${2:-haptic-game}
die() { echo "bundle-runtime: $*" >&2; exit 1; }

[[ -x $dir/$name.x86_64 && -f $dir/$name.pck ]] || die "$dir holds no exported $name; run 'make export'"
extensions=("$dir"/libhaptics.*.so)
[[ -f ${extensions[0]} ]] || die "$dir holds no extension library"

# Which engine's libraries the template was built against: the project-local (Debian
# testing) root, or, for a template of your own, this system.
root=""
libpath=""
loader=/lib64/ld-linux-x86-64.so.2
if [[ $(tools/godot --which) == *"project-local engine"* ]]; then
  # Engines provisioned before the package file lists were kept get them now.
  [[ -d .engine/files ]] || tools/provision-engine.sh --file-lists .engine >&2
  root=$(realpath .engine/root)
  loader=$root/usr/lib64/ld-linux-x86-64.so.2
  [[ -e $loader ]] || loader=$root/lib64/ld-linux-x86-64.so.2
  libpath=$root/usr/lib/x86_64-linux-gnu:$root/usr/lib/x86_64-linux-gnu/pulseaudio
fi
# Sonames of the GPU driver's interface, taken from the system (tools/dist/README.player.md).
gpu_driver=$(<tools/dist/gpu-driver-sonames.regex)

runtime=$dir/runtime
rm -rf "$runtime" "$dir/licenses" "$dir/$name"
mkdir -p "$runtime/lib" "$dir/licenses"
mv "$dir/$name.x86_64" "$dir/$name.pck" "${extensions[@]}" "$runtime/"

# soname -> file, over the template's and the extension's whole dependency closure, resolved
# exactly as the bundled loader will resolve it (library path first, then the system's).
# Of the libraries Godot and SDL open at run time, libudev (joypad hot-plug) is already
# in the closure through hidapi; X11, Wayland, ALSA, PulseAudio, fontconfig and libdecor
# are linked directly by Debian's build.
declare -A found=() linked_driver=()
for elf in "$runtime/$name.x86_64" "$runtime"/libhaptics.*.so; do
  listing=$("$loader" ${libpath:+--library-path "$libpath"} --list "$elf") ||
    die "cannot list the libraries of $elf"
  if grep -q "not found" <<<"$listing"; then
    grep "not found" <<<"$listing" >&2
    die "$elf needs libraries that are not installed"
  fi
  while read -r soname arrow path _; do
    [[ $arrow == "=>" && $path == /* ]] || continue
    [[ $soname == ld-linux-* || $soname == /* ]] && continue
    if [[ $soname =~ $gpu_driver ]]; then linked_driver[$soname]=$path; else found[$soname]=$path; fi
  done <<<"$listing"
done
for soname in "${!found[@]}"; do cp -L "${found[$soname]}" "$runtime/lib/$soname"; done
if ((${#linked_driver[@]} > 0)); then
  mkdir "$runtime/lib-fallback"
  for soname in "${!linked_driver[@]}"; do
    cp -L "${linked_driver[$soname]}" "$runtime/lib-fallback/$soname"
    # What the stand-in needs must be shipped already: it may not bring a library of its own.
    for needed in $(readelf -d "$runtime/lib-fallback/$soname" | sed -nE 's/.*\(NEEDED\).*\[(.*)\]/\1/p'); do
      [[ -e $runtime/lib/$needed || $needed == ld-linux-x86-64.so.2 ]] ||
        die "the stand-in $soname needs $needed, which the bundle does not ship"
    done
  done
fi
# The loader is named after the game: Godot finds its pack ("<executable>.pck") and the
# extension beside /proc/self/exe, which is the loader when the loader starts the game.
cp -L "$loader" "$runtime/$name.loader"
cp tools/dist/launcher.sh "$dir/$name"
cp tools/dist/fonts.conf "$runtime/fonts.conf"
chmod 755 "$dir/$name" "$runtime/$name.loader"

# Licences: the Debian package each shipped file comes from, and its copyright file.
package_of() { # real path -> package name, or nothing
  local real=$1
  if [[ -n $root && $real == "$root"/* ]]; then
    local rel=${real#"$root"} list
    for list in .engine/files/*.list; do
      grep -qxF "$rel" "$list" && { basename "$list" .list; return; }
    done
  else
    local p
    for p in "$real" "${real#/usr}" "/usr$real"; do
      dpkg-query -S "$p" 2>/dev/null | sed -nE '1s/^([^:,]+)(:[a-z0-9]+)?: .*/\1/p' | grep . && return
    done
  fi
  return 0
}
doc_of() { # package -> its /usr/share/doc folder, in the engine's root or the system
  if [[ -n $root && -e $root/usr/share/doc/$1/copyright ]]; then echo "$root/usr/share/doc/$1"; else
    echo "/usr/share/doc/$1"; fi
}
manifest=$dir/licenses/MANIFEST.txt
{
  echo "# Shipped file, the Debian package it comes from, that package's version."
  echo "# Each package's copyright and licence terms: licenses/<package>/copyright."
} >"$manifest"
loader_real=$(realpath "$loader")
# The template the export used: the one its extension library was built for.
[[ ${extensions[0]} == *template_debug* ]] && flavour=debug || flavour=release
[[ -n $root ]] && template_src=$root/usr/bin/godot-template-$flavour || template_src=""
for entry in "runtime/$name.loader=$loader_real" \
  ${template_src:+"runtime/$name.x86_64=$template_src"} \
  $(for s in "${!found[@]}"; do echo "runtime/lib/$s=$(realpath "${found[$s]}")"; done | sort) \
  $(for s in "${!linked_driver[@]}"; do echo "runtime/lib-fallback/$s=$(realpath "${linked_driver[$s]}")"; done | sort); do
  shipped=${entry%%=*}
  real=${entry#*=}
  pkg=$(package_of "$real")
  [[ -n $pkg ]] || die "no Debian package owns $real: its licence is unknown"
  doc=$(doc_of "$pkg")
  [[ -f $doc/copyright ]] || die "package $pkg has no copyright file in $doc"
  version=$(zcat "$doc/changelog.Debian.gz" 2>/dev/null | sed -nE '1s/^[^ ]+ \(([^)]+)\).*/\1/p' || true)
  mkdir -p "$dir/licenses/$pkg"
  cp -L "$doc/copyright" "$dir/licenses/$pkg/copyright"
  printf '%s\t%s\t%s\n' "$shipped" "$pkg" "${version:-unknown}" >>"$manifest"
done
# The game's own licence, next to those of what it ships.
cp LICENSE "$dir/licenses/LICENSE"
stand_ins="${!linked_driver[*]}"
echo "bundle-runtime: $(ls "$runtime/lib" | wc -l) libraries, stand-ins for the system's" \
  "${stand_ins:-(none)}, $(du -sh "$dir" | cut -f1) in $dir"
