#!/usr/bin/env bash
# What a player gets holds none of our development tools: no shipped library holds the
# scripted device models (make build's development library does; exports ship make
# build-release's), and no pack holds the misbehaving network peer the net tests start (it
# lives in a folder of tests/ that Godot does not scan: exports leave tests/ out, but pack the
# uid cache, which names every scanned file). Checked with strings: type names, messages and
# the class reference in a library; the file paths, which a pack's index and uid cache keep
# in plain text (the device models are C++, so only the library can hold them).
#
#   tools/check-product.sh DIR...   (an export or an unpacked addon; exit 1 on a find)
set -euo pipefail
(($# > 0)) || { echo "usage: tools/check-product.sh DIR..." >&2; exit 2; }
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
done < <(find "$@" \( -name 'libhaptics*.so' -o -name 'libhaptics*.dll' -o -name '*.pck' \) -print0)
((found == 0)) || exit 1
((libraries + packs > 0)) || { echo "check-product: FAIL: no library or pack in $*" >&2; exit 1; }
echo "check-product: $libraries haptics libraries and $packs packs in $*: no scripted device, no rogue peer"
