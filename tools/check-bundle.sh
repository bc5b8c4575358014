#!/usr/bin/env bash
# Static checks of a self-contained Linux build (tools/bundle-runtime.sh), without running it:
#  - every library any shipped ELF file needs is shipped, except the GPU driver's interface
#    (tools/dist/gpu-driver-sonames.regex: libgbm, which Debian's SDL links; its stand-in in
#    runtime/lib-fallback is used only without the system's), and no file carries a DT_RPATH (searched before the
#    loader's --library-path; a DT_RUNPATH is searched after it and so cannot leave the bundle);
#  - the C library symbol versions the shipped files require, against the shipped C library
#    and against Debian 12 (glibc 2.36) and Ubuntu 22.04 (2.35), and the kernel it needs;
#  - the libgbm functions the bundle calls exist in this system's libgbm and in the stand-in.
#
#   tools/check-bundle.sh DIR      (exit 1 on the first failed check)
set -euo pipefail
dir=${1:?usage: tools/check-bundle.sh DIR}
runtime=$dir/runtime
lib=$runtime/lib
fail() { echo "check-bundle: FAIL: $*" >&2; exit 1; }
[[ -x $dir/haptic-game && -x $runtime/haptic-game.loader && -f $lib/libc.so.6 ]] ||
  fail "$dir is not a self-contained build (launcher, runtime/haptic-game.loader, runtime/lib/libc.so.6)"

# The GPU driver's interface, which the bundle leaves to the system.
gpu_driver=$(<"$(dirname "$0")/dist/gpu-driver-sonames.regex")
fallback=$runtime/lib-fallback
elves=("$runtime/haptic-game.x86_64" "$runtime"/libhaptics.*.so "$lib"/*)
[[ -d $fallback ]] && elves+=("$fallback"/*)
needs_glibc=()
for elf in "${elves[@]}"; do
  dynamic=$(readelf -d "$elf")
  grep -q "(RPATH)" <<<"$dynamic" && fail "$(basename "$elf") has a DT_RPATH"
  for needed in $(sed -nE 's/.*\(NEEDED\).*\[(.*)\]/\1/p' <<<"$dynamic"); do
    [[ -e $lib/$needed || $needed == ld-linux-x86-64.so.2 || $needed =~ $gpu_driver ]] ||
      fail "$(basename "$elf") needs $needed, which is not shipped"
  done
  needs_glibc+=($(readelf -V "$elf" | grep -oE "Name: GLIBC_[0-9.]+" | cut -d' ' -f2 || true))
done
max_needed=$(printf '%s\n' "${needs_glibc[@]}" | sort -uV | tail -n 1)
shipped=$(readelf -V "$lib/libc.so.6" | grep -oE "Name: GLIBC_[0-9.]+" | cut -d' ' -f2 | sort -uV | tail -n 1)
[[ $(printf '%s\n' "$max_needed" "$shipped" | sort -V | tail -n 1) == "$shipped" ]] ||
  fail "the bundle needs $max_needed but ships a C library with $shipped"
template_needs=$(readelf -V "$runtime/haptic-game.x86_64" | grep -oE "GLIBC_[0-9.]+" | sort -uV | tail -n 1)
for system in "Debian 12:GLIBC_2.36" "Ubuntu 22.04:GLIBC_2.35"; do
  has=${system#*:}
  if [[ $(printf '%s\n' "$template_needs" "$has" | sort -V | tail -n 1) != "$has" ]]; then
    echo "check-bundle: the template needs $template_needs, ${system%:*} has $has: the shipped C library is required"
  fi
done
kernel=$(file -L "$lib/libc.so.6" | grep -oE "for GNU/Linux [0-9.]+" | awk '{print $3}')
[[ $(printf '%s\n' "$kernel" 5.15 | sort -V | tail -n 1) == 5.15 ]] ||
  fail "the shipped C library needs Linux $kernel, newer than Ubuntu 22.04's 5.15"
echo "check-bundle: ${#elves[@]} ELF files, every needed library shipped, no RPATH;" \
  "newest C library version needed $max_needed, shipped $shipped (Linux $kernel or newer)"

# libgbm comes from the system's Mesa: the functions the bundle calls must be there.
# (awk reads to the end: an early exit would kill ldconfig with SIGPIPE, failing the pipe.)
wanted=$(for elf in "${elves[@]}"; do nm -D --undefined-only "$elf" 2>/dev/null; done |
  awk '$2 ~ /^gbm_/ {print $2}' | sort -u)
[[ -z $wanted || -f $fallback/libgbm.so.1 ]] ||
  fail "the bundle calls libgbm but ships no stand-in for a system without it (runtime/lib-fallback)"
system_gbm=$(/sbin/ldconfig -p | awk '$1 == "libgbm.so.1" && /x86-64/ && !seen++ {print $NF}')
for gbm in ${system_gbm:+"$system_gbm"} ${wanted:+"$fallback/libgbm.so.1"}; do
  missing=$(comm -23 <(echo "$wanted") <(nm -D --defined-only "$gbm" | awk '{print $3}' | sort -u))
  [[ -z $missing ]] || fail "$gbm lacks: $missing"
  echo "check-bundle: the $(wc -w <<<"$wanted") libgbm functions the bundle calls are all in $gbm"
done
[[ -n $system_gbm ]] || echo "check-bundle: no libgbm.so.1 on this system; the stand-in's were checked"
