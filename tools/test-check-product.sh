#!/usr/bin/env bash
# The test of tools/check-product.sh, without exporting (make lint): it builds fake exports
# and addons in a temporary folder, each a Godot pack written as Godot 4.6 writes one
# (tools/product_check.py) or a folder of text files, beside a stand-in library, and expects
#  - a clean one to pass, with a class cache and a uid cache that list tests/ as real
#    exports' do;
#  - a pack to fail for every driver class (each class_name declared under tests/ and
#    tools/) named in a packed scene, for a packed file under tests/, for a driver's path
#    in the project settings, for a driver class the class cache declares at a product
#    path, and for the rogue peer's name;
#  - a library holding the scripted devices to fail;
#  - an unpacked addon to fail for a script that names a driver class.
# SHOW=1 prints what check-product said in each case.
set -euo pipefail
cd "$(dirname "$0")/.."
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mapfile -t drivers < <(python3 tools/product_check.py drivers)
((${#drivers[@]} > 0)) || { echo "test-check-product: FAIL: no driver class found" >&2; exit 1; }
failures=0
cases=0

# Writes the pack $1/runtime/game.pck from the clean files plus "PATH=CONTENT" arguments
# (CONTENT, with Python's backslash escapes such as \0, replaces a clean file of the same
# PATH), and a clean stand-in library beside it.
make_export() {
  local dir=$1
  shift
  mkdir -p "$dir/runtime"
  printf 'ELF product library: HapticsSystem, servo, renderers\n' \
    >"$dir/runtime/libhaptics.linux.template_release.x86_64.so"
  python3 - "$dir/runtime/game.pck" "${drivers[@]}" -- "$@" <<'PY'
import sys

sys.path.insert(0, "tools")
import product_check

out = sys.argv[1]
split = sys.argv.index("--")
classes, extra = sys.argv[2:split], sys.argv[split + 1 :]
entries = [("Main", "res://game/main/main.gd")]
entries += [(name, f"res://tests/drivers/{name.lower()}.gd") for name in classes]
cache = "list=[" + ", ".join(
    '{\n"base": &"Node",\n"class": &"%s",\n"language": &"GDScript",\n"path": "%s"\n}' % entry
    for entry in entries
) + "]\n"
files = {
    "game/main/main.gdc": b"GDSC\x65\x00\x00\x00(\xb5/\xfd compressed tokens",
    "game/main/main.gd.remap": b'[remap]\n\npath="res://game/main/main.gdc"\n',
    "game/main/main.tscn.remap": b'[remap]\n\npath="res://.godot/exported/1/export-a-main.scn"\n',
    ".godot/exported/1/export-a-main.scn": b"RSRC\x00Main\x00Background\x00res://game/main/main.gd",
    ".godot/global_script_class_cache.cfg": cache.encode(),
    ".godot/uid_cache.bin": b"\x01\x00res://tests/drivers/game_autopilot.tscn\x00"
    + b"res://tests/runner/test_suite.gd\x00res://tools/dist/controls.gd\x00",
    "project.binary": b'ECFG application/run/main_scene "res://game/main/main.tscn"',
}
for argument in extra:
    path, _, content = argument.partition("=")
    files[path] = content.encode("latin-1").decode("unicode_escape").encode("latin-1")
product_check.write_pack(out, sorted(files.items()))
PY
}

# Runs check-product on $2 and expects $1 (pass or fail); $3 says what the case is.
expect() {
  local want=$1 dir=$2 what=$3 got=pass
  cases=$((cases + 1))
  bash tools/check-product.sh "$dir" >"$tmp/out" 2>&1 || got=fail
  if [[ -n ${SHOW:-} ]]; then echo "[$what]" && sed 's/^/    /' "$tmp/out"; fi
  if [[ $got != "$want" ]]; then
    echo "test-check-product: FAIL: $what: check-product said $got, not $want" >&2
    sed 's/^/    /' "$tmp/out" >&2
    failures=$((failures + 1))
  fi
}

make_export "$tmp/clean"
expect pass "$tmp/clean" "a clean export"

for class in "${drivers[@]}"; do
  make_export "$tmp/scene-$class" ".godot/exported/1/export-b-level.scn=RSRC\0Level\0$class\0"
  expect fail "$tmp/scene-$class" "a packed scene naming the driver class $class"
done

make_export "$tmp/packed" "tests/drivers/level_pilot.gdc=GDSC compressed tokens" \
  'tests/drivers/level_pilot.gd.remap=[remap] path="res://tests/drivers/level_pilot.gdc"'
expect fail "$tmp/packed" "a pack holding a file of tests/"

make_export "$tmp/settings" 'project.binary=ECFG main_scene "res://tests/drivers/game_autopilot.tscn"'
expect fail "$tmp/settings" "project settings naming a driver's scene"

make_export "$tmp/declared" \
  ".godot/global_script_class_cache.cfg=list=[{\"class\": &\"${drivers[0]}\", \"path\": \"res://game/x.gd\"}]"
expect fail "$tmp/declared" "a product script declaring the driver class ${drivers[0]}"

make_export "$tmp/rogue" "game/pong/net/pong_net_peer.gdc=GDSC the rogue peer"
expect fail "$tmp/rogue" "the rogue peer"

make_export "$tmp/scripted"
printf 'scripted:hid device model\n' >>"$tmp/scripted/runtime/libhaptics.linux.template_release.x86_64.so"
expect fail "$tmp/scripted" "a library holding the scripted devices"

# Unpacked addons: the real addon's text files, then one with a script naming a driver.
mkdir -p "$tmp/addon/bin"
git ls-files addons/haptics | grep -v '/bin/' | while IFS= read -r file; do
  [[ -f $file ]] && install -D -m 644 "$file" "$tmp/addon/$file"
done
cp "$tmp/clean/runtime/libhaptics.linux.template_release.x86_64.so" "$tmp/addon/bin/"
expect pass "$tmp/addon" "the addon's own files"
cp -a "$tmp/addon" "$tmp/addon-driver"
printf 'extends Node\n\nvar pilot: %s = null\n' "${drivers[0]}" >"$tmp/addon-driver/addons/haptics/probe/x.gd"
expect fail "$tmp/addon-driver" "an addon script naming the driver class ${drivers[0]}"

((failures == 0)) || { echo "test-check-product: $failures of $cases cases failed" >&2; exit 1; }
echo "test-check-product: $cases cases as expected (clean exports and addons pass; each of" \
  "${#drivers[@]} driver classes, a tests/ file, a driver path, a declared driver class, the rogue" \
  "peer and the scripted devices fail)"
