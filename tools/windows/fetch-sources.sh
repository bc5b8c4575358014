#!/usr/bin/env bash
# Fetches the sources of the libraries the Windows build links statically (hidapi, libusb):
# the upstream release tarball of each pinned Debian source package
# (tools/windows/versions.sh), into .build/windows-deps/src/<package>/ (ignored). apt checks
# the tarball against the checksum in the suite's Sources index, whose signature it checks
# against Debian's archive keyring. Debian's own packaging (its patches are about building
# Debian's packages) is not needed for a Windows build and not fetched. A fetched source is
# reused (a stamp names its version).
#   tools/windows/fetch-sources.sh      prints one "<package> <version> <folder>" line each
set -euo pipefail
project=$(cd "$(dirname "$0")/../.." && pwd)
source "$project/tools/windows/versions.sh"
dir=$project/.build/windows-deps
die() { echo "windows/fetch-sources: $*" >&2; exit 1; }

fetched() { [[ -f $dir/src/$1/.fetched && $(cat "$dir/src/$1/.fetched") == "$2" ]]; }

need=()
suites=()
for package in "${!WINDOWS_DEP_VERSIONS[@]}"; do
  read -r suite _ <<<"${WINDOWS_DEP_VERSIONS[$package]}"
  [[ " ${suites[*]} " == *" $suite "* ]] || suites+=("$suite")
  fetched "$package" "${WINDOWS_DEP_VERSIONS[$package]}" || need+=("$package")
done
if ((${#need[@]} > 0)); then
  source "$project/tools/apt-private.sh"
  apt_private_init "$dir/apt" "${suites[0]}" || die "no Debian archive keyring"
  list=$dir/apt/etc/sources.list
  line=$(sed 's/^deb /deb-src /' "$list")
  for suite in "${suites[@]}"; do
    sed -E "s/ ${suites[0]} main$/ $suite main/" <<<"$line"
  done >"$list"
  apt_opts "$dir/apt/cache"
  apt-get "${opts[@]}" -qq update || die "cannot read the source indexes of Debian's ${suites[*]}"
  for package in "${need[@]}"; do
    read -r _ version <<<"${WINDOWS_DEP_VERSIONS[$package]}"
    work=$dir/download/$package
    rm -rf "$work" "$dir/src/$package"
    mkdir -p "$work" "$dir/src/$package"
    (cd "$work" && apt-get "${opts[@]}" -qq source --download-only --tar-only "$package=$version") ||
      die "cannot download the source of $package $version (has Debian replaced it?)"
    tarball=$(find "$work" -maxdepth 1 -name '*.orig.tar.*' ! -name '*.asc' | head -n 1)
    [[ -n $tarball ]] || die "apt left no upstream tarball of $package $version"
    tar -xf "$tarball" -C "$dir/src/$package" --strip-components=1 ||
      die "cannot unpack $(basename "$tarball")"
    printf '%s\n' "${WINDOWS_DEP_VERSIONS[$package]}" >"$dir/src/$package/.fetched"
    rm -rf "$work"
  done
fi
for package in "${!WINDOWS_DEP_VERSIONS[@]}"; do
  echo "$package ${WINDOWS_DEP_VERSIONS[$package]} $dir/src/$package"
done
