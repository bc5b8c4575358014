#!/usr/bin/env bash
# Fetches a Debian kernel for the VM tests into .kernel/<suite>/ (ignored): the kernel image
# and its modules, with modules.dep made by depmod. The version is the one the suite's
# linux-image-amd64 depends on, so it follows Debian's updates; a fetched kernel is reused
# (delete .kernel/<suite> for a newer one). Nothing else is downloaded.
#   tools/kernel/fetch.sh SUITE     bookworm (Debian 12) or testing; prints the kernel version
set -euo pipefail
project=$(cd "$(dirname "$0")/../.." && pwd)
suite=${1:?usage: tools/kernel/fetch.sh SUITE}
dir=$project/.kernel/$suite
die() { echo "kernel/fetch: $*" >&2; exit 1; }

if [[ -f $dir/.fetched ]]; then
  cat "$dir/.fetched"
  exit 0
fi
command -v depmod >/dev/null || die "depmod missing (package kmod; make deps installs it)"
source "$project/tools/apt-private.sh"
rm -rf "$dir"
mkdir -p "$dir/debs"
apt_private_init "$dir/apt" "$suite" || die "no Debian archive keyring"
apt_opts "$dir/apt/cache"
apt-get "${opts[@]}" -qq update || die "cannot read Debian's '$suite' package index"
# The versioned image the metapackage depends on (its name carries the ABI number).
image=$(apt-cache "${opts[@]}" depends linux-image-amd64 2>/dev/null |
  sed -nE 's/^ *Depends: (linux-image-[0-9][^ ]*-amd64)$/\1/p' | head -n 1)
[[ -n $image ]] || die "linux-image-amd64 in '$suite' names no kernel image"
(cd "$dir/debs" && apt-get "${opts[@]}" -qq download "$image") || die "cannot download $image"
dpkg-deb -x "$dir/debs/$image"_*.deb "$dir/root"
# Newer packages ship their modules under /usr/lib/modules, where Debian 12's depmod does not
# look.
if [[ ! -d $dir/root/lib/modules && -d $dir/root/usr/lib/modules ]]; then
  mkdir -p "$dir/root/lib"
  ln -s ../usr/lib/modules "$dir/root/lib/modules"
fi
version=${image#linux-image-}
[[ -d $dir/root/lib/modules/$version ]] || version=$(ls "$dir/root/lib/modules" | head -n 1)
kernel=$(ls "$dir/root/boot/vmlinuz-"* 2>/dev/null | head -n 1)
[[ -n $kernel ]] || die "$image holds no /boot/vmlinuz"
depmod -b "$dir/root" "$version"
rm -rf "$dir/debs" "$dir/apt/cache"
printf '%s\n' "$version" >"$dir/.fetched"
echo "$version"
