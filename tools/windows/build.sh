#!/usr/bin/env bash
# make build-windows: the extension for Windows x86_64, cross-compiled with MinGW-w64 against
# the interface header the project's engine dumps (the same one the Linux build uses), as
# addons/haptics/bin/libhaptics.windows.template_{debug,release}.x86_64.dll, with hidapi and
# libusb and SDL 3 (tools/windows/build-deps.sh) and the C/C++ runtimes linked in; then the
# doctest suite (.build/windows-debug/haptics_tests.exe, for make test-windows), and the import
# check. Run it through `nice -n 19` on a shared machine (the Makefile does).
# HAPTICS_WINDOWS_BUILD=DIR builds into DIR-debug and DIR-release instead of .build/windows-*,
# and HAPTICS_WINDOWS_ADDON=DIR puts the DLLs in DIR/bin (a copy of addons/haptics), so a second
# build in the same tree leaves the first one's alone (tools/windows/test.sh takes the same).
set -euo pipefail
project=$(cd "$(dirname "$0")/../.." && pwd)
cd "$project"
start=$(date +%s)
prefix=$(tools/windows/build-deps.sh)
build=${HAPTICS_WINDOWS_BUILD:-.build/windows}
addon=$(realpath -m "${HAPTICS_WINDOWS_ADDON:-addons/haptics}")
if [[ ! -f $addon/plugin.cfg ]]; then
  mkdir -p "$addon/bin" && cp addons/haptics/plugin.cfg "$addon/"
fi
generator=Ninja
command -v ninja >/dev/null || generator="Unix Makefiles"
configure() {
  cmake -S gdextension -B "$1" -G "$generator" -Wno-dev \
    -DCMAKE_TOOLCHAIN_FILE="$project/gdextension/cmake/mingw-w64.cmake" \
    -DHAPTICS_WINDOWS_DEPS="$prefix" -DGODOT_RUNNER="$project/tools/godot" -DHAPTICS_ADDON_DIR="$addon" \
    "${@:2}" >/dev/null
}
# The debug library carries the development tools, as on Linux; the doctests come with it.
configure "$build-debug" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DHAPTICS_TARGET=template_debug \
  -DHAPTICS_DEV_TOOLS=ON -DHAPTICS_BUILD_BENCH=OFF
cmake --build "$build-debug" -j 2 --target haptics haptics_tests haptics_load_host
configure "$build-release" -DCMAKE_BUILD_TYPE=Release -DHAPTICS_TARGET=template_release \
  -DHAPTICS_DEV_TOOLS=OFF -DHAPTICS_BUILD_TESTS=OFF -DHAPTICS_BUILD_BENCH=OFF
cmake --build "$build-release" -j 2 --target haptics
for flavour in debug release; do
  tools/windows/check-imports.sh "$addon/bin/libhaptics.windows.template_$flavour.x86_64.dll"
done
echo "build-windows: done in $(($(date +%s) - start)) s"
