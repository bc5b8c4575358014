#!/usr/bin/env bash
# Installs the OS packages the build and tests need, only those missing, with apt-get
# (through sudo when not root). A no-op costing one dpkg-query when all are present.
set -euo pipefail

packages=(build-essential cmake ninja-build pkg-config libhidapi-dev libusb-1.0-0-dev
  doctest-dev clang-format python3 python3-venv debian-archive-keyring ca-certificates
  rt-tests xvfb openbox patchelf qemu-system-x86 busybox-static kmod libdbus-1-dev rtkit dbus
  polkitd util-linux debootstrap
  # make test-rt and make bench give the user /dev/cpu_dma_latency as the udev rule does (an ACL).
  acl
  # The net suite's connect floods run in a network namespace, the server behind the kernel
  # guard tools/net/flood-guard.sh installs (tests/net/flood_harness.py).
  iproute2 nftables
  # The scripted person (tests/person/): input events, screenshots and OCR of the screen, and
  # a desktop's sound server (with a null sink: this machine has no sound card).
  xdotool imagemagick tesseract-ocr tesseract-ocr-eng pulseaudio
  # The Windows build (tools/windows/): MinGW-w64 (the posix thread model: std::thread) and
  # Wine to run its doctests.
  g++-mingw-w64-x86-64-posix wine64)

if ! command -v dpkg-query >/dev/null || ! command -v apt-get >/dev/null; then
  echo "install-deps: no apt here; install yourself: a C++20 compiler, CMake 3.22+, Ninja," \
    "pkg-config, hidapi, libusb-1.0, doctest, clang-format, Python 3 with venv, cyclictest" \
    "(rt-tests), Xvfb and openbox for the benchmark and the windowed tests, patchelf; and Godot 4.5+" \
    "(GODOT=...)." >&2
  exit 0
fi

# SDL 3's headers for the SDL backend, from Debian testing (Debian 12 has none): two packages
# unpacked into .build/deps/sdl3, not installed (tools/provision-sdl3.sh, pinned there). Without
# them the build leaves the backend out and says so. After the packages (it needs the keyring).
provision_sdl3() {
  "$(dirname "$0")/provision-sdl3.sh" >/dev/null ||
    echo "install-deps: SDL 3 could not be provisioned; the SDL backend will not be built" >&2
}

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${db:Status-Status}' "$p" 2>/dev/null || true)
  [[ $status == installed ]] || missing+=("$p")
done
if ((${#missing[@]} == 0)); then
  provision_sdl3
  exit 0
fi

sudo=()
if [[ $(id -u) -ne 0 ]]; then
  command -v sudo >/dev/null || {
    echo "install-deps: need root or sudo to install: ${missing[*]}" >&2
    exit 1
  }
  sudo=(sudo)
fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -qq
"${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
provision_sdl3
