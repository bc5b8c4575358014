#!/usr/bin/env bash
# A minimal Debian root for the bare-system test (tools/bare/test-bare.sh): debootstrap's
# minbase variant (the Essential packages, apt and the required-priority ones: no graphics
# package, no X, no Mesa) of a pinned suite from the system's Debian mirror, with an ordinary
# user 'player' (uid 1000) to run the game as. Built once into .bare/SUITE/root and reused;
# the packages stay in .bare/cache/SUITE, so a root built again is not downloaded again.
#
#   tools/bare/root.sh SUITE   (bookworm: Debian 12; bullseye: Debian 11) prints the root
set -euo pipefail
cd "$(dirname "$0")/../.."
source tools/apt-private.sh
suite=${1:?usage: tools/bare/root.sh bookworm|bullseye}
case $suite in
  bookworm | bullseye) ;;
  *) echo "root: suite '$suite' is not one the test pins (bookworm, bullseye)" >&2; exit 2 ;;
esac
dir=$PWD/.bare/$suite
root=$dir/root
if [[ -f $dir/ready ]]; then
  echo "$root"
  exit 0
fi
command -v debootstrap >/dev/null || { echo "root: debootstrap is missing (make deps)" >&2; exit 1; }
[[ $(id -u) -eq 0 ]] || { echo "root: debootstrap needs root" >&2; exit 1; }
[[ -r $keyring ]] || { echo "root: missing $keyring (make deps)" >&2; exit 1; }
cache=$PWD/.bare/cache/$suite
mkdir -p "$cache" "$dir"
rm -rf "$root.partial"
started=$SECONDS
debootstrap --variant=minbase --keyring="$keyring" --cache-dir="$cache" \
  "$suite" "$root.partial" "$(apt_mirror)" >"$dir/debootstrap.log" 2>&1 ||
  { tail -n 20 "$dir/debootstrap.log" >&2; echo "root: debootstrap $suite failed" >&2; exit 1; }
chroot "$root.partial" useradd --create-home --uid 1000 --shell /bin/sh player
# The apt lists and the packages' copies inside the root are not needed to run anything.
rm -rf "$root.partial"/var/cache/apt/archives/*.deb "$root.partial"/var/lib/apt/lists/*
rm -rf "$root"
mv "$root.partial" "$root"
echo "$suite $(du -sh "$root" | cut -f1) $((SECONDS - started)) s" >"$dir/ready"
echo "root: built $suite in $((SECONDS - started)) s, $(du -sh "$root" | cut -f1)" >&2
echo "$root"
