#!/usr/bin/env bash
# The exported Linux builds on bare systems (make test-bare): minimal Debian roots without a
# graphics package (tools/bare/root.sh), each run in its own mount, PID and network namespace
# (chroot; /proc of its own; no network but its own loopback), the game started by the
# ordinary user 'player' with an emptied environment:
#  - Debian 12: the game headless under its system check (it shows its main menu for a
#    moment; an export holds no test driver, so no autopilot: docs/testing.md) and the
#    dedicated Pong server for a few seconds start, run and exit 0 without an ERROR line; the
#    same start without the
#    launcher's stand-in for the missing libgbm fails (the root really lacks it);
#  - Debian 11: the headless game runs too; a windowed start stops at once with the launcher's
#    message naming the system's glibc as the cause (its graphics driver cannot load beside
#    the shipped C library), not the engine's message box about the video driver.
# Needs root (debootstrap, chroot, namespaces). The first run builds both roots (minutes),
# later runs reuse them (timings: docs/supported-systems.md).
set -euo pipefail
cd "$(dirname "$0")/../.."
game_build=.export/linux
server_build=.export/linux-server
for build in $game_build/haptic-game $server_build/haptic-pong-server; do
  [[ -x $build ]] || { echo "test-bare: $build missing; run 'make export export-server'" >&2; exit 1; }
done
[[ $(id -u) -eq 0 ]] || { echo "test-bare: needs root (debootstrap, chroot, namespaces)" >&2; exit 1; }
gpu_driver=$(<tools/dist/gpu-driver-sonames.regex)
# Each run's bound, wall seconds (far above a headless run's few seconds).
run_seconds=120

pid=""
root=""
tmp=$(mktemp -d /tmp/haptic-bare-test.XXXXXX)
log=$tmp/run.log
cleanup() {
  if [[ -n $pid ]]; then
    kill "$pid" 2>/dev/null || true
    wait "$pid" 2>/dev/null || true
  fi
  [[ -n $root ]] && rm -rf "$root/home/player/run"
  rm -rf "$tmp"
}
trap cleanup EXIT
fail() {
  echo "test-bare: FAIL: $1"
  [[ -n ${2:-} && -f $2 ]] && tail -n 20 "$2"
  exit 1
}

# Runs "$@" in $root as 'player' (emptied environment, HOME and the working folder
# /home/player/run) in new mount, PID and network namespaces, at most run_seconds; the
# output goes to $log, the exit status to $status. --kill-child takes the whole PID namespace
# down with unshare, so stopping unshare's PID stops everything the run started.
run_as_player() {
  # shellcheck disable=SC2016 # expanded by the inner shell
  timeout --kill-after=5 "$run_seconds" unshare --mount --pid --net --fork --kill-child \
    bash -c 'mount -t proc proc "$1/proc" && root=$1 && shift &&
      exec chroot "$root" setpriv --reuid=player --regid=player --init-groups \
        env -i HOME=/home/player PATH=/usr/bin:/bin LANG=C.UTF-8 \
        sh -c "cd /home/player/run && exec \"\$@\"" - "$@"' - "$root" "$@" >"$log" 2>&1 &
  pid=$!
  status=0
  wait "$pid" || status=$?
  pid=""
}
# Engine and script errors in $log.
errors() { grep -cE "^(ERROR|SCRIPT ERROR|USER ERROR)|[Ee]rror:" "$log" || true; }

# Copies the builds into the root, owned by 'player'.
install_builds() {
  rm -rf "$root/home/player/run"
  mkdir "$root/home/player/run"
  cp -a "$game_build" "$root/home/player/run/haptic-game"
  cp -a "$server_build" "$root/home/player/run/haptic-pong-server"
  chown -R 1000:1000 "$root/home/player/run"
}

# A root without the graphics stack: no library of the GPU driver's interface anywhere.
check_bare() {
  local found
  found=$(find "$root/usr/lib" "$root/usr/local/lib" -name '*.so*' 2>/dev/null |
    xargs -r -n 1 basename | grep -E "$gpu_driver" || true)
  [[ -z $found ]] || fail "$1: the root holds GPU driver libraries: $found"
}

game=./haptic-game/haptic-game
server=./haptic-pong-server/haptic-pong-server

# --- Debian 12 ---
root=$(tools/bare/root.sh bookworm)
check_bare "Debian 12"
install_builds

# The engine started without the launcher's stand-in: what a player saw before.
run_as_player ./haptic-game/runtime/haptic-game.loader --library-path ./haptic-game/runtime/lib \
  ./haptic-game/runtime/haptic-game.x86_64 --headless --version
((status != 0)) && grep -q "libgbm.so.1" "$log" ||
  fail "Debian 12: the engine started without libgbm: the root is not bare (status $status)" "$log"

started=$SECONDS
run_as_player "$game" --headless -- --system-check
((status == 0)) || fail "Debian 12: the headless game exited with $status" "$log"
grep -q "haptics [0-9.]* (Godot" "$log" || fail "Debian 12: the bundled extension did not load" "$log"
grep -q "^System check: the main menu showed" "$log" || fail "Debian 12: the main menu did not show" "$log"
(($(errors) == 0)) || fail "Debian 12: the headless game printed $(errors) error lines" "$log"
echo "test-bare: Debian 12, player, headless game's system check: exit 0, no error line" \
  "($((SECONDS - started)) s)"

started=$SECONDS
run_as_player "$server" --headless -- --server --port=7420 --pong-net-max-seconds=3
((status == 0)) || fail "Debian 12: the server exited with $status" "$log"
grep -q "(dedicated server)" "$log" || fail "Debian 12: the server did not announce itself" "$log"
(($(errors) == 0)) || fail "Debian 12: the server printed $(errors) error lines" "$log"
echo "test-bare: Debian 12, player, dedicated server for 3 s: exit 0, no error line" \
  "($((SECONDS - started)) s)"
rm -rf "$root/home/player/run"

# --- Debian 11: older than the shipped C library's graphics drivers can be ---
root=$(tools/bare/root.sh bullseye)
check_bare "Debian 11"
install_builds
run_as_player "$game" --headless -- --system-check
((status == 0)) || fail "Debian 11: the headless game exited with $status" "$log"
grep -q "^System check: the main menu showed" "$log" || fail "Debian 11: the main menu did not show" "$log"
(($(errors) == 0)) || fail "Debian 11: the headless game printed $(errors) error lines" "$log"
echo "test-bare: Debian 11, player, headless game's system check: exit 0, no error line"

run_as_player "$game" -- --system-check
((status == 1)) || fail "Debian 11: a windowed start exited with $status, not the launcher's 1" "$log"
grep -q "this system's C library is glibc 2.31" "$log" ||
  fail "Debian 11: the launcher did not name the system's C library" "$log"
! grep -q "Godot Engine" "$log" || fail "Debian 11: the engine started: the launcher let it" "$log"
echo "test-bare: Debian 11, player, windowed: stopped by the launcher: $(head -n 1 "$log")"
rm -rf "$root/home/player/run"
