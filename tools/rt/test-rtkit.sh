#!/usr/bin/env bash
# The servo as a player's ordinary user gets it (make test-rt): a private system bus, polkitd
# and RealtimeKit's rtkit-daemon (Debian's own, started for the test only), and
# haptics_rt_probe run as an unprivileged user (nobody). What the kernel says about the servo
# thread (/proc/self/task/<tid>/stat) must be what the servo's stats say:
#   1. RealtimeKit allowed (a polkit rule for that user, as a desktop session has): SCHED_RR at
#      the priority the daemon allows;
#   2. real time not allowed, a higher priority allowed: SCHED_OTHER at the daemon's nice;
#   3. no RealtimeKit on the bus: SCHED_OTHER, and the stats say RealtimeKit is unavailable.
# Needs root to start the daemons (CI runs as root). No timing is asserted. Everything it
# starts is stopped by PID on exit.
#   tools/rt/test-rtkit.sh PROBE
set -euo pipefail
probe=${1:?usage: tools/rt/test-rtkit.sh PROBE}
user=nobody
die() { echo "test-rt: $*" >&2; exit 1; }

[[ $(id -u) -eq 0 ]] || die "needs root, to start a private system bus and rtkit-daemon (run it with sudo)"
[[ -x $probe ]] || die "no probe at $probe"
for tool in dbus-daemon dbus-send unshare setpriv; do
  command -v "$tool" >/dev/null || die "$tool missing (make deps installs it)"
done
rtkit=/usr/libexec/rtkit-daemon
polkitd=/usr/lib/polkit-1/polkitd
[[ -x $rtkit ]] || die "$rtkit missing (package rtkit; make deps installs it)"
[[ -x $polkitd ]] || die "$polkitd missing (package polkitd; make deps installs it)"
id "$user" >/dev/null 2>&1 || die "no user '$user' to run the probe as"

work=$(mktemp -d "${TMPDIR:-/tmp}/haptics-rt.XXXXXX")
chmod 755 "$work"
pids=()
cleanup() {
  local pid
  for pid in "${pids[@]}"; do
    kill "$pid" 2>/dev/null || true
  done
  for pid in "${pids[@]}"; do
    for _ in $(seq 50); do
      kill -0 "$pid" 2>/dev/null || break
      sleep 0.1
    done
    kill -9 "$pid" 2>/dev/null || true
  done
  rm -rf "$work"
}
trap cleanup EXIT

# The system bus's own configuration, on a socket of ours, without activation (nothing else
# starts), forking or logging to syslog; the services' policies (rtkit's, polkit's) included.
socket=$work/system_bus_socket
sed -e "s|<listen>.*</listen>|<listen>unix:path=$socket</listen>|" \
  -e '/<fork\/>/d' -e '/<pidfile>/d' -e '/<syslog\/>/d' -e '/<standard_system_servicedirs\/>/d' \
  -e '/<servicehelper>/d' -e 's|<includedir>system.d</includedir>|<includedir>/usr/share/dbus-1/system.d</includedir>|' \
  /usr/share/dbus-1/system.conf >"$work/bus.conf"
dbus-daemon --config-file="$work/bus.conf" --nofork --nopidfile >"$work/bus.log" 2>&1 &
pids+=($!)
export DBUS_SYSTEM_BUS_ADDRESS=unix:path=$socket

has_owner() {
  dbus-send --system --print-reply --dest=org.freedesktop.DBus /org/freedesktop/DBus \
    org.freedesktop.DBus.NameHasOwner "string:$1" 2>/dev/null | grep -q 'boolean true'
}
wait_for() {
  for _ in $(seq 100); do
    has_owner "$1" && return 0
    sleep 0.1
  done
  die "$1 did not appear on the private bus (logs in $work)"
}
wait_for org.freedesktop.DBus

# polkitd reads its rules from /etc/polkit-1/rules.d: in a mount namespace of its own that
# folder is ours, so the machine's rules are untouched.
start_polkit() {
  mkdir -p "$work/rules"
  cat >"$work/rules/50-haptics-test.rules"
  unshare --mount --propagation private sh -c \
    "mount --bind '$work/rules' /etc/polkit-1/rules.d && exec $polkitd --no-debug" >"$work/polkit.log" 2>&1 &
  pids+=($!)
  wait_for org.freedesktop.PolicyKit1
}
# rtkit-daemon sets its own RLIMIT_FSIZE to 0: its log goes through a pipe (RT.md).
start_rtkit() {
  "$rtkit" --no-canary --stderr 2> >(cat >"$work/rtkit.log") >/dev/null &
  pids+=($!)
  wait_for org.freedesktop.RealtimeKit1
}
stop_last() {
  local pid=${pids[-1]}
  kill "$pid"
  wait "$pid" 2>/dev/null || true
  unset 'pids[-1]'
}

run_probe() {
  setpriv --reuid="$user" --regid="$(id -g "$user")" --clear-groups --inh-caps=-all \
    env -i DBUS_SYSTEM_BUS_ADDRESS="$DBUS_SYSTEM_BUS_ADDRESS" PATH=/usr/bin:/bin "$probe"
}
field() { sed -nE "s/.*[ ]$1=\"?([^\" ]*).*/\1/p" <<<"$2" | head -n 1; }
failures=0
expect() {
  if [[ $2 == "$3" ]]; then
    echo "test-rt: PASS $1: $2"
  else
    echo "test-rt: FAIL $1: $2 (expected $3)"
    failures=$((failures + 1))
  fi
}

allow_rules() {
  printf 'polkit.addRule(function(action, subject) {\n'
  printf '  if (subject.user == "%s" && (%s)) { return polkit.Result.YES; }\n' "$user" "$1"
  printf '});\n'
}

echo "test-rt: 1. RealtimeKit allows real time to '$user'"
allow_rules 'action.id.indexOf("org.freedesktop.RealtimeKit1.") == 0' | start_polkit
start_rtkit
out=$(run_probe) || die "the probe failed: $out"
echo "$out"
kernel=$(grep 'RTPROBE kernel' <<<"$out")
stats=$(grep 'RTPROBE stats' <<<"$out")
expect "the kernel runs the servo thread at" "$(field policy "$kernel")" SCHED_RR
expect "its priority is the one the stats report" "$(field rt_priority "$kernel")" "$(field priority "$stats")"
expect "which is the daemon's maximum" "$(field priority "$stats")" "$(field rtkit_max "$stats")"
expect "the stats say" "$(field scheduler "$stats")" SCHED_RR
stop_last # rtkit
stop_last # polkit

echo "test-rt: 2. RealtimeKit allows '$user' a higher priority only"
allow_rules 'action.id == "org.freedesktop.RealtimeKit1.acquire-high-priority"' | start_polkit
start_rtkit
out=$(run_probe) || die "the probe failed: $out"
echo "$out"
kernel=$(grep 'RTPROBE kernel' <<<"$out")
stats=$(grep 'RTPROBE stats' <<<"$out")
expect "the kernel runs the servo thread at" "$(field policy "$kernel")" SCHED_OTHER
expect "its nice level is the one the stats report" "$(field nice "$kernel")" "$(field nice "$stats")"
expect "RealtimeKit's answer in the stats" "$(sed -nE 's/.*realtime_kit="([^"]*)".*/\1/p' <<<"$stats")" "high priority"
stop_last
stop_last

echo "test-rt: 3. no RealtimeKit on the bus"
out=$(run_probe) || die "the probe failed: $out"
echo "$out"
kernel=$(grep 'RTPROBE kernel' <<<"$out")
stats=$(grep 'RTPROBE stats' <<<"$out")
expect "the kernel runs the servo thread at" "$(field policy "$kernel")" SCHED_OTHER
expect "the stats say" "$(field scheduler "$stats")" SCHED_OTHER
expect "RealtimeKit's answer in the stats" "$(sed -nE 's/.*realtime_kit="([^"]*)".*/\1/p' <<<"$stats")" unavailable

((failures == 0)) || die "$failures check(s) failed (logs: $work is removed; rerun with the daemons' output above)"
echo "test-rt: all checks passed"
