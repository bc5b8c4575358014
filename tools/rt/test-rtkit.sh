#!/usr/bin/env bash
# The servo as a player's ordinary user gets it (make test-rt): RealtimeKit as a desktop has it
# (tools/rt/private-rtkit.sh: a private system bus, polkitd, Debian's rtkit-daemon) and
# haptics_rt_probe run as the unprivileged user nobody. What the kernel says about the servo
# thread (/proc/self/task/<tid>/stat) must be what the servo's stats say:
#   1. RealtimeKit allows real time (a polkit rule for that user, as a desktop session has):
#      SCHED_RR at the highest priority the daemon allows; without the udev rule no latency
#      hold, and the spin is learned;
#   2. the same with /dev/cpu_dma_latency given to the user as the udev rule gives it (an ACL
#      entry, rw; the file's ACL is restored after): the hold is taken while the servo runs
#      (the kernel's target reads 0, the process has the file open) and released when it stops;
#   3. it allows only a higher priority: SCHED_OTHER at the daemon's lowest nice level;
#   4. no RealtimeKit on the bus: SCHED_OTHER, and the stats say it is unavailable.
# Needs root to start the daemons (CI runs as root). No timing is asserted.
#   tools/rt/test-rtkit.sh PROBE
set -euo pipefail
probe=${1:?usage: tools/rt/test-rtkit.sh PROBE}
[[ -x $probe ]] || { echo "test-rt: no probe at $probe" >&2; exit 1; }
source "$(dirname "$0")/private-rtkit.sh"
rtkit_setup nobody
# The user runs a copy where it may: the build folder can sit in a private temporary folder
# (a fresh clone in mktemp -d is 0700).
cp "$probe" "$rtkit_work/haptics_rt_probe"
chmod 755 "$rtkit_work/haptics_rt_probe"
probe=$rtkit_work/haptics_rt_probe

failures=0
expect() {
  if [[ $2 == "$3" ]]; then
    echo "test-rt: PASS $1: $2"
  else
    echo "test-rt: FAIL $1: $2 (expected $3)"
    failures=$((failures + 1))
  fi
}
# The value of key=value (or key="value") in a probe line.
field() { sed -nE "s/.* $1=(\"([^\"]*)\"|([^ ]*)).*/\2\3/p" <<<"$2" | head -n 1; }
probe_lines() {
  out=$(rtkit_as_user "$probe") || rtkit_die "the probe failed: $out"
  echo "$out"
  kernel=$(grep 'RTPROBE kernel' <<<"$out")
  stats=$(grep 'RTPROBE stats' <<<"$out")
  latency=$(grep 'RTPROBE latency' <<<"$out")
  expect "the probe runs as" "$(sed -nE 's/.*euid=([0-9]+).*/\1/p' <<<"$out")" "$(id -u nobody)"
}

echo "test-rt: 1. RealtimeKit allows real time"
rtkit_start_polkit 'action.id.indexOf("org.freedesktop.RealtimeKit1.") == 0'
rtkit_start_daemon
probe_lines
expect "the kernel runs the servo thread at" "$(field policy "$kernel")" SCHED_RR
expect "its priority is the one the stats report" "$(field rt_priority "$kernel")" "$(field priority "$stats")"
expect "which is the daemon's maximum" "$(field priority "$stats")" "$(field rtkit_max "$stats")"
expect "the stats say" "$(field scheduler "$stats")" SCHED_RR
expect "without the udev rule the latency is not held" "$(field held "$latency")" 0
expect "nor is the file open while the servo runs" "$(field running_open "$latency")" 0
expect "so the spin is learned" "$(field spin_learned "$latency")" 1
expect "from the unheld spin (us)" "$(field spin_us "$stats")" "$(field unheld_spin_us "$stats")"

echo "test-rt: 2. RealtimeKit, and /dev/cpu_dma_latency given to the user as the udev rule gives it"
rtkit_grant_latency
probe_lines
rtkit_revoke_latency
expect "the stats say the latency is held" "$(field held "$latency")" 1
expect "the process holds the file open while the servo runs" "$(field running_open "$latency")" 1
expect "the kernel's CPU latency target while it runs (us)" "$(field running_us "$latency")" 0
expect "the file is closed once the servo stopped" "$(field stopped_open "$latency")" 0
expect "a servo with the hold spins the held spin (us)" "$(field spin_us "$stats")" "$(field held_spin_us "$stats")"
expect "and does not learn it" "$(field spin_learned "$latency")" 0
expect "the kernel runs the servo thread at" "$(field policy "$kernel")" SCHED_RR
# The target is the least of every open request: another process's (a benchmark or test
# beside this one) would hide ours going, so it is read between two looks for other holders.
others=$(rtkit_latency_holders)
target_after=$(od -An -td4 -N4 "$rtkit_latency_file" | tr -d ' ')
others+=$(rtkit_latency_holders)
if [[ -z $others ]]; then
  released() { if [[ $1 -ne 0 ]]; then echo "released ($1)"; else echo "still 0"; fi; }
  expect "the kernel's target after the probe exited" "$(released "$target_after")" "released ($target_after)"
  expect "and once the servo stopped, as the probe read it" "$(released "$(field stopped_us "$latency")")" \
    "released ($(field stopped_us "$latency"))"
else
  echo "test-rt: NOTE the target after exit is not read: other processes hold the file ($(tr '\n' ' ' <<<"$others"))"
fi
expect "the file's ACL gives the user nothing once taken back" "$(getfacl -cp "$rtkit_latency_file" | grep -c "^user:nobody:" || true)" 0
rtkit_stop_last
rtkit_stop_last

echo "test-rt: 3. RealtimeKit allows a higher priority only"
rtkit_start_polkit 'action.id == "org.freedesktop.RealtimeKit1.acquire-high-priority"'
rtkit_start_daemon
probe_lines
expect "the kernel runs the servo thread at" "$(field policy "$kernel")" SCHED_OTHER
expect "its nice level is the one the stats report" "$(field nice "$kernel")" "$(field nice "$stats")"
expect "RealtimeKit's answer in the stats" "$(field realtime_kit "$stats")" "high priority"
expect "a servo without real time does not spin (us)" "$(field spin_us "$stats")" 0
rtkit_stop_last
rtkit_stop_last

echo "test-rt: 4. no RealtimeKit on the bus"
probe_lines
expect "the kernel runs the servo thread at" "$(field policy "$kernel")" SCHED_OTHER
expect "the stats say" "$(field scheduler "$stats")" SCHED_OTHER
expect "RealtimeKit's answer in the stats" "$(field realtime_kit "$stats")" unavailable
expect "a servo without real time does not spin (us)" "$(field spin_us "$stats")" 0

rtkit_cleanup
left=0
for pid in "${rtkit_started[@]}"; do
  kill -0 "$pid" 2>/dev/null && left=$((left + 1))
done
expect "daemons left running of the ${#rtkit_started[@]} started" "$left" 0
expect "processes of nobody left running" "$(pgrep -c -u nobody || true)" 0
acl_line() { grep -v '^$' | tr '\n' ' '; }
expect "the ACL of $rtkit_latency_file as found" "$(getfacl -cp "$rtkit_latency_file" | acl_line)" \
  "$(acl_line <<<"$rtkit_latency_acl")"

((failures == 0)) || rtkit_die "$failures check(s) failed"
echo "test-rt: all checks passed"
