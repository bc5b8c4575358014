#!/usr/bin/env bash
# Boots a Debian kernel under QEMU (software emulation by default; KERNEL_TEST_ACCEL=kvm where
# KVM runs a stock kernel) with the VM test program (gdextension/vm_tests) in its initramfs,
# reads what it prints on the serial console and fails on any failed check, a missing end, or
# the timeout.
#   tools/kernel/run.sh PROGRAM [SUITE [SCENARIO,...]]   SUITE: bookworm (default) or testing
# The console log is .build/kernel/<suite>.log (or $HAPTICS_KERNEL_OUT/<suite>.log).
set -euo pipefail
project=$(cd "$(dirname "$0")/../.." && pwd)
program=${1:?usage: tools/kernel/run.sh PROGRAM [SUITE [SCENARIO,...]]}
suite=${2:-bookworm}
scenarios=${3:-}
# Guest seconds are several host seconds under emulation on a loaded machine.
timeout_s=${KERNEL_TEST_TIMEOUT:-300}
# KVM only when asked: on machines whose /dev/kvm is a paravirtual KVM (kvm_pvm) a stock
# kernel hangs under it without a word (docs/linux-kernel.md), and the timeout would be all
# we learn.
accel=${KERNEL_TEST_ACCEL:-tcg}
case $accel in
  tcg) cpu=max ;;
  kvm) cpu=host ;;
  *) echo "kernel/run: KERNEL_TEST_ACCEL must be tcg or kvm (got '$accel')" >&2; exit 2 ;;
esac
die() { echo "kernel/run: $*" >&2; exit 1; }

qemu=$(command -v qemu-system-x86_64) || die "qemu-system-x86_64 missing (package qemu-system-x86; make deps installs it)"
version=$("$project/tools/kernel/fetch.sh" "$suite" | tail -n 1) || die "could not fetch the '$suite' kernel"
kernel_dir=$project/.kernel/$suite/root
image=$project/.kernel/$suite/vmlinuz
out=${HAPTICS_KERNEL_OUT:-$project/.build/kernel} # Its own folder lets two runs go side by side.
mkdir -p "$out"
"$project/tools/kernel/initramfs.sh" "$kernel_dir" "$version" "$program" "$out/$suite.cpio.gz" >/dev/null ||
  die "could not pack the initramfs"
log=$out/$suite.log
# oops=panic: a guest kernel oops ends the VM at once instead of hanging it until the timeout.
boot() {
  status=0
  timeout "$timeout_s" "$qemu" -accel "$accel" -cpu "$cpu" -m 512M -smp 2 -nographic -no-reboot \
    -kernel "$image" -initrd "$out/$suite.cpio.gz" \
    -append "console=ttyS0 panic=-1 oops=panic rdinit=/init loglevel=4 ktest.scenarios=$scenarios" \
    </dev/null >"$log" 2>&1 || status=$?
  tr -d '\r' <"$log" >"$log.txt" && mv "$log.txt" "$log"
}
# The guest's emulated USB controller (dummy_hcd under FunctionFS) can oops on its own while
# a gadget is replugged; that is the test rig's kernel failing, not the code under test, so
# it earns one more boot, and says so. Any other oops fails the run.
rig_oops() {
  grep -qE '^\[ *[0-9.]+\] (BUG:|Oops:|general protection)' "$log" &&
    grep -qE '(dummy_queue|dummy_timer|usb_ep_queue|ffs_epfile_io)\+' "$log"
}
start=$(date +%s)
boot
if rig_oops; then
  mv "$log" "$log.rig-oops"
  echo "kernel/run: the guest kernel oopsed in its emulated USB controller (dummy_hcd, log kept in $log.rig-oops); booting once more" >&2
  boot
fi
seconds=$(($(date +%s) - start))

grep -E '^(KTEST|KWIRE|KINFO)' "$log" | sed "s/^/[$suite] /"
((status != 124)) || die "the VM did not finish within ${timeout_s} s (log: $log)"
! grep -qE '^\[ *[0-9.]+\] (BUG:|Oops:|general protection)' "$log" ||
  die "the guest kernel oopsed (log: $log)"
grep -q '^KTEST-KERNEL ' "$log" || die "the VM did not reach the test program (log: $log)"
grep -q '^KTEST-DONE ' "$log" || die "the test program did not finish (log: $log)"
failures=$(grep -cE '^KTEST( .* FAIL |-SETUP FAIL)' "$log" || true)
checks=$(grep -cE '^KTEST [^ ]+ (PASS|FAIL) ' "$log" || true)
((failures == 0)) && grep -q '^KTEST-EXIT 0$' "$log" ||
  die "$failures of $checks checks failed on $(grep -m1 '^KTEST-KERNEL' "$log" | cut -d' ' -f2) (log: $log)"
echo "kernel/run: $suite, Linux $version: $checks checks passed in ${seconds} s"
