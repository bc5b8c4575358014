# Sourced by tools/rt/test-rtkit.sh and tools/rt/bench-users.sh: RealtimeKit for an ordinary
# user, as a desktop has it, started for one test or benchmark: a private system bus (the
# system's own configuration on a socket of ours, without activation, forking or syslog),
# polkitd with rules of ours in a mount namespace of its own (the machine's rules are not
# touched), and Debian's rtkit-daemon. Needs root. Everything started is stopped by PID when
# the calling script exits (rtkit_cleanup, set as its EXIT trap by rtkit_setup).
#   rtkit_setup USER               checks the tools, makes the work folder, starts the bus and
#                                  exports DBUS_SYSTEM_BUS_ADDRESS
#   rtkit_start_polkit JS_CONDITION  polkitd allowing USER the actions the condition names
#                                  (a JavaScript expression on `action`)
#   rtkit_start_daemon             rtkit-daemon (no canary: short runs)
#   rtkit_stop_last                stops the most recently started one
#   rtkit_as_user COMMAND...       runs COMMAND as USER, without capabilities, on the bus
#   rtkit_grant_latency / rtkit_revoke_latency
#                                  give USER /dev/cpu_dma_latency as the project's udev rule
#                                  gives the logged-in user (an ACL entry, rw), and take it back
#   rtkit_latency_holders          the PIDs holding /dev/cpu_dma_latency open
#   rtkit_cleanup                  stops everything and restores the file's ACL (also on exit)
rtkit_user=""
rtkit_work=""
rtkit_pids=()
rtkit_started=() # Every PID started, for the callers that check none is left.
rtkit_daemon=/usr/libexec/rtkit-daemon
rtkit_polkitd=/usr/lib/polkit-1/polkitd
rtkit_latency_file=/dev/cpu_dma_latency
rtkit_latency_acl="" # The file's ACL as found, restored by rtkit_cleanup.

rtkit_die() { echo "rtkit: $*" >&2; exit 1; }

rtkit_cleanup() {
  local pid
  for pid in "${rtkit_pids[@]}"; do
    kill "$pid" 2>/dev/null || true
  done
  for pid in "${rtkit_pids[@]}"; do
    for _ in $(seq 50); do
      kill -0 "$pid" 2>/dev/null || break
      sleep 0.1
    done
    kill -9 "$pid" 2>/dev/null || true
  done
  rtkit_pids=()
  if [[ -n $rtkit_latency_acl ]]; then
    setfacl --set-file=- "$rtkit_latency_file" <<<"$rtkit_latency_acl" ||
      echo "rtkit: could not restore the ACL of $rtkit_latency_file" >&2
  fi
  [[ -z $rtkit_work ]] || rm -rf "$rtkit_work"
}

rtkit_grant_latency() {
  setfacl -m "u:$rtkit_user:rw" "$rtkit_latency_file"
}

rtkit_revoke_latency() {
  setfacl -x "u:$rtkit_user" "$rtkit_latency_file"
}

rtkit_latency_holders() {
  local fd
  for fd in /proc/[0-9]*/fd/*; do
    if [[ $(readlink "$fd" 2>/dev/null) == "$rtkit_latency_file" ]]; then
      echo "${fd%/fd/*}" | cut -d/ -f3
    fi
  done | sort -u
}

rtkit_has_owner() {
  dbus-send --system --print-reply --dest=org.freedesktop.DBus /org/freedesktop/DBus \
    org.freedesktop.DBus.NameHasOwner "string:$1" 2>/dev/null | grep -q 'boolean true'
}

rtkit_wait_for() {
  for _ in $(seq 100); do
    rtkit_has_owner "$1" && return 0
    sleep 0.1
  done
  rtkit_die "$1 did not appear on the private bus"
}

rtkit_setup() {
  rtkit_user=${1:?}
  [[ $(id -u) -eq 0 ]] || rtkit_die "needs root, to start a private system bus and rtkit-daemon"
  local tool
  for tool in dbus-daemon dbus-send unshare setpriv getfacl setfacl; do
    command -v "$tool" >/dev/null || rtkit_die "$tool missing (make deps installs it)"
  done
  [[ -x $rtkit_daemon ]] || rtkit_die "$rtkit_daemon missing (package rtkit; make deps installs it)"
  [[ -x $rtkit_polkitd ]] || rtkit_die "$rtkit_polkitd missing (package polkitd; make deps installs it)"
  id "$rtkit_user" >/dev/null 2>&1 || rtkit_die "no user '$rtkit_user'"
  rtkit_work=$(mktemp -d "${TMPDIR:-/tmp}/haptics-rtkit.XXXXXX")
  chmod 755 "$rtkit_work"
  if [[ -e $rtkit_latency_file ]]; then
    rtkit_latency_acl=$(getfacl -cp "$rtkit_latency_file")
  fi
  trap rtkit_cleanup EXIT
  local socket=$rtkit_work/system_bus_socket
  sed -e "s|<listen>.*</listen>|<listen>unix:path=$socket</listen>|" \
    -e '/<fork\/>/d' -e '/<pidfile>/d' -e '/<syslog\/>/d' -e '/<standard_system_servicedirs\/>/d' \
    -e '/<servicehelper>/d' \
    -e 's|<includedir>system.d</includedir>|<includedir>/usr/share/dbus-1/system.d</includedir>|' \
    /usr/share/dbus-1/system.conf >"$rtkit_work/bus.conf"
  dbus-daemon --config-file="$rtkit_work/bus.conf" --nofork --nopidfile >"$rtkit_work/bus.log" 2>&1 &
  rtkit_pids+=($!)
  rtkit_started+=($!)
  export DBUS_SYSTEM_BUS_ADDRESS=unix:path=$socket
  rtkit_wait_for org.freedesktop.DBus
}

rtkit_start_polkit() {
  local condition=${1:?}
  mkdir -p "$rtkit_work/rules"
  cat >"$rtkit_work/rules/50-haptics.rules" <<RULES
polkit.addRule(function(action, subject) {
  if (subject.user == "$rtkit_user" && ($condition)) { return polkit.Result.YES; }
});
RULES
  unshare --mount --propagation private sh -c \
    "mount --bind '$rtkit_work/rules' /etc/polkit-1/rules.d && exec $rtkit_polkitd --no-debug" \
    >"$rtkit_work/polkit.log" 2>&1 &
  rtkit_pids+=($!)
  rtkit_started+=($!)
  rtkit_wait_for org.freedesktop.PolicyKit1
}

# rtkit-daemon sets its own RLIMIT_FSIZE to 0: its log goes through a pipe (docs/realtime.md).
rtkit_start_daemon() {
  "$rtkit_daemon" --no-canary --stderr 2> >(cat >"$rtkit_work/rtkit.log") >/dev/null &
  rtkit_pids+=($!)
  rtkit_started+=($!)
  rtkit_wait_for org.freedesktop.RealtimeKit1
}

rtkit_stop_last() {
  local pid=${rtkit_pids[-1]}
  kill "$pid" 2>/dev/null || true
  wait "$pid" 2>/dev/null || true
  unset 'rtkit_pids[-1]'
}

rtkit_as_user() {
  setpriv --reuid="$rtkit_user" --regid="$(id -g "$rtkit_user")" --clear-groups --inh-caps=-all \
    env -i DBUS_SYSTEM_BUS_ADDRESS="$DBUS_SYSTEM_BUS_ADDRESS" PATH=/usr/bin:/bin HOME=/nonexistent "$@"
}
