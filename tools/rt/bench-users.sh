#!/usr/bin/env bash
# make bench's real-time benchmark with the player's case beside root's: haptics_rt_bench runs
# as root (as shipped: SCHED_FIFO, /dev/cpu_dma_latency) and, in the same rounds under the
# same loads, measures the servo as the ordinary user nobody without RealtimeKit and with it
# (tools/rt/private-rtkit.sh: a private system bus, polkitd allowing nobody real time as a
# desktop session would, Debian's rtkit-daemon), with the spin it learns, the fixed spin, and
# /dev/cpu_dma_latency given to nobody as the udev rule gives the player (an ACL entry the
# benchmark adds for those rows and takes back; the file's ACL as found is restored on exit
# whatever happens). Every tick of every round is pooled per row. Without root it runs the
# benchmark alone, as whoever runs it.
#   tools/rt/bench-users.sh BENCH PROJECT JSON [haptics_rt_bench options...]
set -euo pipefail
bench=${1:?usage: tools/rt/bench-users.sh BENCH PROJECT JSON [options]}
project=${2:?}
json=${3:?}
shift 3
if [[ $(id -u) -ne 0 ]]; then
  echo "bench-users: not root: the servo is measured as $(id -un) only"
  exec "$bench" --project "$project" --json "$json" "$@"
fi
source "$(dirname "$0")/private-rtkit.sh"
rtkit_setup nobody
rtkit_start_polkit 'action.id.indexOf("org.freedesktop.RealtimeKit1.") == 0'
rtkit_start_daemon
# The user runs this same binary: a copy where it may (the build folder may sit in a private
# temporary folder).
cp "$bench" "$rtkit_work/haptics_rt_bench"
chmod 755 "$rtkit_work/haptics_rt_bench"
bus=$DBUS_SYSTEM_BUS_ADDRESS
# Root's own servo gets SCHED_FIFO and never asks RealtimeKit: keep it off the private bus.
env -u DBUS_SYSTEM_BUS_ADDRESS "$rtkit_work/haptics_rt_bench" --project "$project" --json "$json" \
  --user nobody --rtkit-bus "$bus" "$@"
