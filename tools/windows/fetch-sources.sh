#!/usr/bin/env bash
# Fetches the sources of the libraries the Windows build links statically (hidapi, libusb)
# from Debian 12's source packages into .build/windows-deps/src/<package>/ (ignored), pinned
# by version: apt verifies each file against the checksums of the signed Sources index, and
# dpkg-source against the .dsc. A fetched source is reused (a stamp names its version).
#   tools/windows/fetch-sources.sh      prints one "<package> <version> <folder>" line each
set -euo pipefail
project=$(cd "$(dirname "$0")/../.." && pwd)
source "$project/tools/windows/versions.sh"
dir=$project/.build/windows-deps
die() { echo "windows/fetch-sources: $*" >&2; exit 1; }
command -v dpkg-source >/dev/null || die "dpkg-source missing (package dpkg-dev; make deps installs it)"

fetched() { [[ -f $dir/src/$1/.fetched && $(cat "$dir/src/$1/.fetched") == "$2" ]]; }

need=()
for package in "${!WINDOWS_DEP_VERSIONS[@]}"; do
  fetched "$package" "${WINDOWS_DEP_VERSIONS[$package]}" || need+=("$package")
done
if ((${#need[@]} > 0)); then
  source "$project/tools/apt-private.sh"
  apt_private_init "$dir/apt" "$WINDOWS_DEP_SUITE" || die "no Debian archive keyring"
  sed 's/^deb /deb-src /' "$dir/apt/etc/sources.list" >>"$dir/apt/etc/sources.list"
  apt_opts "$dir/apt/cache"
  apt-get "${opts[@]}" -qq update || die "cannot read Debian's '$WINDOWS_DEP_SUITE' source index"
  for package in "${need[@]}"; do
    version=${WINDOWS_DEP_VERSIONS[$package]}
    work=$dir/download/$package
    rm -rf "$work" "$dir/src/$package"
    mkdir -p "$work"
    (cd "$work" && apt-get "${opts[@]}" -qq source --download-only "$package=$version") ||
      die "cannot download the source of $package $version (has Debian replaced it?)"
    # dpkg-source checks every file against the .dsc's checksums and applies Debian's patches.
    # It cannot check the maintainer's signature (no Debian keyring of uploaders): apt has
    # already checked the .dsc itself against the archive's signed index.
    mkdir -p "$dir/src"
    (cd "$work" && dpkg-source --no-copy -x ./*.dsc "$dir/src/$package" >"$work/unpack.log" 2>&1) ||
      { cat "$work/unpack.log" >&2; die "cannot unpack the source of $package $version"; }
    printf '%s\n' "$version" >"$dir/src/$package/.fetched"
    rm -rf "$work"
  done
fi
for package in "${!WINDOWS_DEP_VERSIONS[@]}"; do
  echo "$package ${WINDOWS_DEP_VERSIONS[$package]} $dir/src/$package"
done
