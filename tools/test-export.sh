#!/usr/bin/env bash
# Checks that the exported build is self-contained and runs: a copy of .export/linux/ in a
# temporary folder outside the project is started through its launcher with an emptied
# environment (env -i: HOME in the temporary folder, the system's PATH, no .engine/ anywhere),
# headless, then in a window on Xvfb with the system's GPU driver, each time under the game's
# own system check (-- --system-check: it prints what it found and shows the main menu for
# a moment; an export holds no test driver, so the autopilot runs only from the source tree:
# tools/test-windowed.sh, docs/testing.md). Each run must load the bundled extension, show
# the menu, print no error and exit 0, and every shared
# object mapped into it (/proc/<pid>/maps, sampled while it runs) must come from the bundle,
# except, in the window, the system's GPU driver and what that driver itself links.
# tools/check-bundle.sh checks the bundle's files first.
set -euo pipefail
cd "$(dirname "$0")/.."
name=haptic-game
build=.export/linux
[[ -x $build/$name && -x $build/runtime/$name.loader ]] ||
  { echo "test-export: $build is not a self-contained build; run 'make export'" >&2; exit 1; }

source tools/xvfb.sh
tmp=$(mktemp -d /tmp/haptic-export-test.XXXXXX)
pid=""
cleanup() {
  if [[ -n $pid ]]; then
    kill "$pid" 2>/dev/null || true
    wait "$pid" 2>/dev/null || true
  fi
  xvfb_stop
  rm -rf "$tmp"
}
trap cleanup EXIT
game=$tmp/game
cp -a "$build" "$game"
mkdir "$tmp/home"
log=$tmp/game.log
fail() {
  echo "test-export: FAIL: $1"
  [[ -f $log ]] && tail -n 20 "$log"
  exit 1
}
tools/check-bundle.sh "$game" || fail "the bundle's static checks"
tools/check-product.sh "$game" || fail "development tools in the export"
# Sonames of the GPU driver's interface, which the bundle leaves to the system.
gpu_driver=$(<tools/dist/gpu-driver-sonames.regex)

# A command run_game's environment goes through first (none: the machine as it is).
wrap=()
# Starts the launcher with an emptied environment plus "$@" (VAR=value words first), from
# the temporary home, samples its memory maps until it exits (at most 120 s), and leaves
# its exit status in $status and the mapped shared objects in $tmp/objects.
run_game() {
  local vars=()
  while [[ $1 == *=* ]]; do vars+=("$1"); shift; done
  : >"$tmp/maps"
  (cd "$tmp/home" && exec "${wrap[@]}" env -i HOME="$tmp/home" PATH=/usr/local/bin:/usr/bin:/bin \
    LANG=C.UTF-8 "${vars[@]}" "$game/$name" "$@") >"$log" 2>&1 &
  pid=$!
  local deadline=$((SECONDS + 120))
  while kill -0 "$pid" 2>/dev/null; do
    # Only once the launcher has handed over to the bundled loader (before, it is env or sh).
    if [[ $(readlink "/proc/$pid/exe" 2>/dev/null) == "$game/runtime/$name.loader" ]]; then
      cat "/proc/$pid/maps" >>"$tmp/maps" 2>/dev/null || true
    fi
    ((SECONDS < deadline)) || { kill "$pid"; break; }
    sleep 0.2
  done
  status=0
  wait "$pid" || status=$?
  pid=""
  awk '$6 ~ /\.so(\.[0-9]+)*$|\.loader$|\.x86_64$/ {print $6}' "$tmp/maps" | sort -u >"$tmp/objects"
}

# The checks the game's own output allows (as before the bundle): extension, main menu, no
# error and no leak, not even at exit (CleanExit keeps the engine's own exit noise of the
# release template from the player: tools/bare/repro-disconnect.sh).
check_output() {
  ((status == 0)) || fail "$1: exit status $status"
  grep -q "haptics [0-9.]* (Godot" "$log" || fail "$1: the bundled extension did not load"
  grep -q "^System check: the main menu showed" "$log" || fail "$1: the main menu did not show"
  if grep -E "^(ERROR|SCRIPT ERROR)" "$log"; then
    fail "$1: errors were printed"
  fi
  if grep -E "leaked at exit|still in use at exit" "$log"; then
    fail "$1: leaks were reported at exit"
  fi
  grep -q "^$game/runtime/lib/libc.so.6$" "$tmp/objects" || fail "$1: the bundled C library was not mapped"
  ! grep -q "\.engine/" "$tmp/objects" || fail "$1: a library of .engine/ was loaded"
}

# Every mapped object outside the bundle must be the GPU driver's (libgbm is linked by SDL
# even headless) or one the driver links; none may stand in for a library the bundle ships.
check_objects() {
  local driver allowed object
  driver=$(grep -v "^$game/" "$tmp/objects" | while read -r object; do
    [[ $(basename "$object") =~ $gpu_driver || $object == */dri/* || $object == */gbm/* ]] &&
      echo "$object"
  done || true)
  allowed=$(if [[ -n $driver ]]; then
    (echo "$driver"; ldd $driver | awk '$3 ~ /^\// {print $3}') | xargs -n 1 realpath | sort -u
  fi)
  while read -r object; do
    [[ $object == "$game/"* ]] && continue
    [[ -e $game/runtime/lib/$(basename "$object") ]] &&
      fail "$1: $object was loaded instead of the bundled $(basename "$object")"
    grep -qxF "$(realpath "$object")" <<<"$allowed" ||
      fail "$1: $object is neither in the bundle nor part of the GPU driver"
  done <"$tmp/objects"
  from_driver=$(grep -vc "^$game/" "$tmp/objects" || true)
  from_bundle=$(grep -c "^$game/" "$tmp/objects")
  driver_names=$(grep -v "^$game/" "$tmp/objects" | xargs -r -n 1 basename | tr '\n' ' ')
}

run_game --headless -- --system-check
check_output headless
check_objects headless
echo "test-export: headless, emptied environment: exit 0, extension loaded; mapped:" \
  "$from_bundle objects from the bundle, $from_driver from the system's GPU driver ($driver_names)"

# The same on a system that has nothing but the C library (which the launcher's sh, env,
# readlink and dirname need) and the GPU driver seen above: in a private mount namespace,
# the system's library folder is replaced by one holding only those. Needs the right to
# create a mount namespace (root, as CI runs); without it this part is skipped, and says so.
multiarch=/usr/lib/x86_64-linux-gnu
if [[ -L /lib && -d $multiarch ]] && unshare -m true 2>/dev/null; then
  mkdir "$tmp/syslib"
  for object in $(ldd /bin/sh /usr/bin/env /usr/bin/readlink /usr/bin/dirname |
    awk '$3 ~ /^\// {print $3} $1 ~ /^\/.*ld-linux/ {print $1}' | sort -u) \
    $(grep -v "^$game/" "$tmp/objects" || true); do
    soname=$(readelf -d "$object" | sed -nE 's/.*\(SONAME\).*\[(.*)\]/\1/p')
    cp -L "$object" "$tmp/syslib/${soname:-$(basename "$object")}"
  done
  wrap=(unshare -m bash -c 'mount --bind "$1" "$2" && shift 2 && exec "$@"' - "$tmp/syslib" "$multiarch")
  run_game --headless -- --system-check
  wrap=()
  check_output "system library folder emptied"
  check_objects "system library folder emptied"
  echo "test-export: headless, emptied environment, system library folder holding only" \
    "$(ls "$tmp/syslib" | tr '\n' ' ')(a mount namespace): exit 0, extension loaded"
else
  echo "test-export: SKIPPED the run with the system library folder emptied (no mount namespace here)"
fi

# In a window: the system's GPU driver may add its own objects, nothing else.
xvfb_start "$tmp" || fail "no display"
run_game DISPLAY="$XVFB_DISPLAY" --rendering-driver opengl3 --audio-driver Dummy \
  -- --system-check
check_output windowed
grep -q "OpenGL API" "$log" || fail "windowed: no OpenGL context was reported"
check_objects windowed
[[ $driver_names == *libGL* || $driver_names == *libEGL* ]] || fail "windowed: no OpenGL library was loaded"
echo "test-export: windowed (Xvfb), emptied environment: exit 0; mapped: $from_bundle objects" \
  "from the bundle, $from_driver from the system's GPU driver; $(grep "OpenGL API" "$log" | head -n 1)"

# Files the game reads as plain files, not resources, must be in the pack too: the engine
# opens the pack alone (from a folder without a project) and looks for each.
cat >"$tmp/pack_check.gd" <<'GD'
extends SceneTree


func _initialize() -> void:
	var missing: PackedStringArray = []
	for path: String in OS.get_cmdline_user_args():
		if not FileAccess.file_exists(path):
			missing.append(path)
	print("pack check: " + (", ".join(missing) + " missing" if not missing.is_empty() else "ok"))
	quit(1 if not missing.is_empty() else 0)
GD
godot_runner=$(pwd)/tools/godot
(cd "$tmp/home" && "$godot_runner" --headless --main-pack "$game/runtime/$name.pck" \
  -s "$tmp/pack_check.gd" -- res://assets/study/consent.txt res://assets/study/study_schema.json \
  res://assets/study/study_config.json >"$tmp/pack.log" 2>&1) ||
  { grep "pack check" "$tmp/pack.log"; fail "the pack lacks files the game reads"; }
echo "test-export: study files packed"
