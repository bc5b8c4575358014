#!/usr/bin/env bash
# Packs the VM's initramfs: busybox (static, from the busybox-static package), the drivers the
# tests use with the modules they depend on (in load order), the test program with the shared
# libraries it links (from this machine; with Debian testing's C library and libSDL3 when the
# program has the SDL backend) and tools/kernel/init.
#   tools/kernel/initramfs.sh KERNEL_DIR VERSION TEST_PROGRAM OUT.cpio.gz
set -euo pipefail
project=$(cd "$(dirname "$0")/../.." && pwd)
kernel_dir=${1:?} version=${2:?} program=${3:?} out=${4:?}
die() { echo "kernel/initramfs: $*" >&2; exit 1; }
# The drivers the scenarios need: uhid and hid-generic give hidraw nodes, hid-playstation the
# DualSense's evdev node, uinput user-space force feedback, evdev the event nodes; usbhid and
# hid-pidff (built into usbhid) a USB HID PID stick, through a FunctionFS gadget on dummy_hcd.
modules=(uhid hid-generic hid-playstation uinput evdev usbhid dummy_hcd libcomposite usb_f_fs)

busybox=$(command -v busybox) || die "busybox missing (package busybox-static; make deps installs it)"
! ldd "$busybox" >/dev/null 2>&1 || die "$busybox is not static (package busybox-static)"
[[ -x $program ]] || die "no test program at $program"

stage=$(mktemp -d "${TMPDIR:-/tmp}/haptics-initramfs.XXXXXX")
trap 'rm -rf "$stage"' EXIT
mkdir -p "$stage"/{bin,dev,proc,sys,tmp,run,modules,tests,lib64,lib/x86_64-linux-gnu}
cp "$busybox" "$stage/bin/busybox"
# Only the applets init uses: linking every name busybox lists would also link "busybox"
# itself over the binary.
for applet in sh mount mkdir insmod sed tr grep dmesg poweroff cat echo sleep ls uname; do
  ln -s busybox "$stage/bin/$applet"
done
cp "$project/tools/kernel/init" "$stage/init"
chmod +x "$stage/init"

# Each module after the ones it needs, each once; built-in ones need no file.
: >"$stage/modules/order"
for module in "${modules[@]}"; do
  while read -r verb path _; do
    [[ $verb == insmod ]] || continue
    name=$(basename "$path")
    name=${name%.xz}
    name=${name%.zst}
    grep -qxF "$name" "$stage/modules/order" && continue
    case $path in
      *.xz) xz -dc "$path" >"$stage/modules/$name" ;;
      *.zst) zstd -qdc "$path" >"$stage/modules/$name" ;;
      *) cp "$path" "$stage/modules/$name" ;;
    esac
    echo "$name" >>"$stage/modules/order"
  done < <(modprobe -d "$kernel_dir" -S "$version" --show-depends "$module" 2>/dev/null ||
    die "no module $module in the kernel $version")
done

cp "$program" "$stage/tests/haptics_vm_tests"
# A program built with the SDL backend loads libSDL3.so.0 at run time (its scenario, sdl):
# Debian testing's, which needs testing's C library. Then the program's libraries, SDL's and
# the loader come from the engine's root (Debian testing, tools/provision-engine.sh), which
# holds the very libSDL3.so.0 the exported game ships, resolved as that loader resolves them
# (the engine's root first, then this machine's); libudev.so.1, which SDL's haptics load, is
# among the program's own.
sdl_root=""
if grep -q "libSDL3.so.0" "$program"; then
  sdl_root=${KERNEL_TEST_SDL_ROOT:-$project/.engine/root}
  [[ -e $sdl_root/usr/lib/x86_64-linux-gnu/libSDL3.so.0 ]] ||
    die "$program loads libSDL3.so.0, and $sdl_root has none (make engine provisions it; or set KERNEL_TEST_SDL_ROOT)"
fi
if [[ -n $sdl_root ]]; then
  loader=$sdl_root/usr/lib64/ld-linux-x86-64.so.2
  [[ -e $loader ]] || loader=$sdl_root/lib64/ld-linux-x86-64.so.2
  libpath=$sdl_root/usr/lib/x86_64-linux-gnu:$sdl_root/usr/lib/x86_64-linux-gnu/pulseaudio
  sdl=$sdl_root/usr/lib/x86_64-linux-gnu/libSDL3.so.0
  while read -r lib; do
    cp -L "$lib" "$stage/lib/x86_64-linux-gnu/"
  done < <(for elf in "$program" "$sdl"; do
    "$loader" --library-path "$libpath" --list "$elf" || die "cannot list the libraries of $elf"
  done | sed -nE 's/.*=> (\/[^ ]+) .*/\1/p' | sort -u)
  cp -L "$sdl" "$stage/lib/x86_64-linux-gnu/"
  cp -L "$loader" "$stage/lib64/ld-linux-x86-64.so.2"
else
  # The program's shared libraries, and the loader, from this machine.
  while read -r lib; do
    cp -L "$lib" "$stage/lib/x86_64-linux-gnu/"
  done < <(ldd "$program" | sed -nE 's/.*=> (\/[^ ]+) .*/\1/p')
  cp -L /lib64/ld-linux-x86-64.so.2 "$stage/lib64/"
fi

(cd "$stage" && find . | busybox cpio -o -H newc 2>/dev/null) | gzip -1 >"$out"
echo "kernel/initramfs: $(wc -l <"$stage/modules/order") modules, $(du -h "$out" | cut -f1)"
