#!/usr/bin/env bash
# What a player gets holds none of our development tools and none of our drivers: no shipped
# library holds the scripted device models (make build's development library does; exports
# ship make build-release's), no pack holds the misbehaving network peer the net tests start
# (it lives in a folder of tests/ that Godot does not scan: exports leave tests/ out, but pack
# the uid cache, which names every scanned file), and no pack or unpacked addon holds or names
# a test, benchmark, trial or demonstration driver: a file under tests/ or tools/, or a class
# one of them declares (tools/product_check.py derives the list from the repository and says
# what a pack may list anyway). Libraries and the rogue peer are checked with strings: type
# names, messages and the class reference in a library, the file paths a pack's index and uid
# cache keep in plain text (the device models are C++, so only the library can hold them).
# Its own test: tools/test-check-product.sh (make lint).
#
#   tools/check-product.sh DIR...   (an export or an unpacked addon; exit 1 on a find)
set -euo pipefail
(($# > 0)) || { echo "usage: tools/check-product.sh DIR..." >&2; exit 2; }
here=$(dirname "$0")
found=0
libraries=0
packs=0
while IFS= read -r -d '' file; do
  case $file in
    *.so | *.dll) pattern=scripted; libraries=$((libraries + 1)) ;;
    *.pck) pattern=rogue; packs=$((packs + 1)) ;;
  esac
  hits=$(strings -a "$file" | grep -iE "$pattern" | sort -u | head -n 5 || true)
  if [[ -n $hits ]]; then
    echo "check-product: FAIL: $file holds development tools:" >&2
    sed 's/^/    /' <<<"$hits" >&2
    found=1
  fi
  if [[ $file == *.pck ]]; then
    python3 "$here/product_check.py" pack "$file" || found=1
  fi
done < <(find "$@" \( -name 'libhaptics*.so' -o -name 'libhaptics*.dll' -o -name '*.pck' \) -print0)
# Unpacked folders (an addon): their scripts, scenes and settings as text.
python3 "$here/product_check.py" tree "$@" || found=1
((found == 0)) || exit 1
((libraries + packs > 0)) || { echo "check-product: FAIL: no library or pack in $*" >&2; exit 1; }
drivers=$(python3 "$here/product_check.py" drivers | wc -l)
echo "check-product: $libraries haptics libraries and $packs packs in $*: no scripted device," \
  "no rogue peer, no driver (nothing of tests/ or tools/, none of their $drivers classes)"
