#!/usr/bin/env bash
# Fetches a Debian kernel for the VM tests into .kernel/<suite>/ (ignored): the kernel image
# (.kernel/<suite>/vmlinuz) and its modules, with modules.dep made by depmod. The version is the one the suite's
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
# Debian 12's image package holds the kernel and its modules; newer ones (7.x) depend on
# linux-binary-<abi> and linux-modules-<abi> for them.
abi=${image#linux-image-}
parts=$(dpkg-deb -f "$dir/debs/$image"_*.deb Depends | tr ',|' '\n\n' |
  sed -nE "s/^ *(linux-(binary|modules)-${abi//+/\\+}) .*/\1/p" | sort -u)
for part in $parts; do
  (cd "$dir/debs" && apt-get "${opts[@]}" -qq download "$part") || die "cannot download $part"
done
for deb in "$dir"/debs/*.deb; do
  dpkg-deb -x "$deb" "$dir/root"
done
# Newer packages ship their modules under /usr/lib/modules, where Debian 12's depmod does not
# look.
if [[ ! -d $dir/root/lib/modules && -d $dir/root/usr/lib/modules ]]; then
  mkdir -p "$dir/root/lib"
  ln -s ../usr/lib/modules "$dir/root/lib/modules"
fi
version=$abi
[[ -d $dir/root/lib/modules/$version ]] || version=$(ls "$dir/root/lib/modules" | head -n 1)
# /boot/vmlinuz-<version> (Debian 12) or /usr/lib/modules/<version>/vmlinuz (7.x).
kernel=""
for candidate in "$dir/root/boot/vmlinuz-"* "$dir/root/lib/modules/$version/vmlinuz"; do
  [[ -f $candidate ]] && kernel=$candidate && break
done
[[ -n $kernel ]] || die "$image holds no kernel image (/boot/vmlinuz-*, /usr/lib/modules/*/vmlinuz)"
ln -sfn "${kernel#"$dir"/}" "$dir/vmlinuz"
# Newer packages leave out modules.order and modules.builtin: depmod warns, and copes.
depmod -b "$dir/root" "$version" 2>/dev/null || die "depmod failed on $version"
rm -rf "$dir/debs" "$dir/apt/cache"
printf '%s\n' "$version" >"$dir/.fetched"
echo "$version"
