#!/usr/bin/env bash
# Provisions a project-local Godot 4 engine (plus export templates and Mesa) from Debian's
# `testing` suite, falling back to `unstable`, using a private apt state so that the
# system's apt configuration is never read or written. Idempotent: a finished root is
# marked by a stamp file and reused at no cost. Each package's file list is kept in
# files/<package>.list (the export's runtime bundle names the packages it ships, and their
# licences, from it).
#
# Usage: tools/provision-engine.sh [ROOT]      (default: .engine in the project)
#        tools/provision-engine.sh --file-lists [ROOT]
# Prints the provisioned version on its last line. --file-lists only writes the file lists of
# an engine provisioned before they were kept, downloading its packages again (at the
# versions of its saved package index); the engine itself is left as it is.
set -euo pipefail

project=$(cd "$(dirname "$0")/.." && pwd)
file_lists_only=false
[[ ${1:-} == --file-lists ]] && { file_lists_only=true; shift; }
# Absolute: apt reads relative paths in its options as relative to /.
engine_dir=$(realpath -m "${1:-"$project/.engine"}")
root="$engine_dir/root"
stamp="$engine_dir/.provisioned"

# Godot itself, the export templates and the Mesa stack the engine's GL loader expects to
# find beside it (mixing the host's older Mesa with the suite's libgl fails under Xvfb).
packages=(godot godot-template-debug godot-template-release
  libgl1-mesa-dri libegl-mesa0 libglx-mesa0 libgl1 libegl1 libgles2 libglx0)

if [[ $file_lists_only == false && -f "$stamp" && -x "$root/usr/bin/godot" ]]; then
  cat "$stamp"
  exit 0
fi

die() { echo "provision-engine: $*" >&2; exit 1; }

if [[ $(uname -s) != Linux || $(uname -m) != x86_64 ]] || ! command -v apt-get >/dev/null \
  || ! command -v dpkg >/dev/null; then
  die "cannot provision Godot here (needs Debian/Ubuntu x86_64 with apt).
Install Godot 4.5 or newer yourself and run again with GODOT=/path/to/godot."
fi

source "$project/tools/apt-private.sh"
[[ -r $keyring ]] || die "missing $keyring: install the 'debian-archive-keyring' package
(or install Godot 4.5+ yourself and set GODOT)."
apt_state="$engine_dir/apt"

# Writes DIR/<package>.list for each .deb given: one absolute path a line (symlinks without
# their target).
write_file_lists() {
  local dir=$1 deb
  shift
  mkdir -p "$dir"
  for deb in "$@"; do
    dpkg-deb -c "$deb" | sed -E 's,^([^ ]+ +){5}\.,,; s, -> .*$,,' \
      >"$dir/$(dpkg-deb -f "$deb" Package).list"
  done
}

if [[ $file_lists_only == true ]]; then
  [[ -f $stamp && -d $apt_state/lists ]] || die "$engine_dir holds no provisioned engine"
  cache=$(mktemp -d)
  trap 'rm -rf "$cache"' EXIT
  mkdir -p "$cache/archives/partial"
  apt_opts "$cache"
  echo "provision-engine: downloading the engine's packages again for their file lists" >&2
  apt-get "${opts[@]}" -qq -y --download-only --no-install-recommends install "${packages[@]}" \
    >/dev/null || die "the engine's packages could not be downloaded again"
  rm -rf "$engine_dir/files.partial"
  write_file_lists "$engine_dir/files.partial" "$cache/archives"/*.deb
  mv "$engine_dir/files.partial" "$engine_dir/files"
  exit 0
fi

start=$(date +%s%N)
rm -rf "$apt_state" "$root" "$engine_dir/files" "$engine_dir/files.partial"
mkdir -p "$apt_state/lists/partial" "$apt_state/cache/archives/partial" "$apt_state/etc" "$root"
: >"$apt_state/status"

fetch() {
  local suite=$1
  apt_private_init "$apt_state" "$suite"
  apt_opts "$apt_state/cache"
  echo "provision-engine: resolving ${packages[*]} from Debian '$suite'"
  apt-get "${opts[@]}" -qq update &&
    apt-get "${opts[@]}" -qq -y --download-only --no-install-recommends install "${packages[@]}" \
      >/dev/null
}

if ! fetch testing; then
  echo "provision-engine: 'testing' could not resolve the packages; trying 'unstable'" >&2
  rm -rf "$apt_state/lists" "$apt_state/cache/archives"/*.deb
  mkdir -p "$apt_state/lists/partial"
  fetch unstable || die "neither testing nor unstable could provide Godot; install Godot 4.5+
yourself and set GODOT=/path/to/godot"
fi

debs=("$apt_state/cache/archives"/*.deb)
echo "provision-engine: unpacking ${#debs[@]} packages into $root"
for deb in "${debs[@]}"; do dpkg-deb -x "$deb" "$root"; done
write_file_lists "$engine_dir/files.partial" "${debs[@]}"
mv "$engine_dir/files.partial" "$engine_dir/files"
rm -rf "$apt_state/cache/archives"

[[ -x "$root/usr/bin/godot" ]] || die "the unpacked root has no usr/bin/godot"
loader="$root/usr/lib64/ld-linux-x86-64.so.2"
[[ -e $loader ]] || loader="$root/lib64/ld-linux-x86-64.so.2"
libs="$root/usr/lib/x86_64-linux-gnu:$root/usr/lib/x86_64-linux-gnu/pulseaudio"
version=$("$loader" --library-path "$libs" "$root/usr/bin/godot" --version 2>/dev/null | tail -n 1)
[[ $version == 4.* ]] || die "the unpacked engine did not report a 4.x version ('$version')"
ms=$((($(date +%s%N) - start) / 1000000))
elapsed="$((ms / 1000)).$(printf %03d $((ms % 1000)))"
echo "Godot $version (Debian, ${#debs[@]} packages, ${elapsed}s)" | tee "$stamp"
