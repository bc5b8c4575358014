#!/usr/bin/env bash
# Builds the static hidapi (its Windows backend), libusb (WinUSB) and SDL 3 (its joystick,
# gamepad and haptic subsystems) for Windows x86_64 with MinGW-w64 from the sources
# tools/windows/fetch-sources.sh fetched, into one install prefix, .build/windows-deps/prefix
# (ignored). Rebuilt only when a pinned version or this script's SDL configuration changes.
#   tools/windows/build-deps.sh      prints the prefix
set -euo pipefail
project=$(cd "$(dirname "$0")/../.." && pwd)
source "$project/tools/windows/versions.sh"
dir=$project/.build/windows-deps
prefix=$dir/prefix
triple=x86_64-w64-mingw32
die() { echo "windows/build-deps: $*" >&2; exit 1; }
command -v "$triple-gcc-posix" >/dev/null ||
  die "$triple-gcc-posix missing (package g++-mingw-w64-x86-64-posix; make deps installs it)"

# SDL's configuration is part of what was built: a change to it rebuilds the prefix.
sdl_options=(-DSDL_STATIC=ON -DSDL_SHARED=OFF -DSDL_TEST_LIBRARY=OFF -DSDL_TESTS=OFF -DSDL_EXAMPLES=OFF
  -DSDL_INSTALL_DOCS=OFF -DSDL_JOYSTICK=ON -DSDL_HAPTIC=ON -DSDL_HIDAPI=ON -DSDL_HIDAPI_JOYSTICK=ON
  -DSDL_HIDAPI_LIBUSB=OFF -DSDL_AUDIO=OFF -DSDL_VIDEO=OFF -DSDL_GPU=OFF
  -DSDL_RENDER=OFF -DSDL_CAMERA=OFF -DSDL_POWER=OFF -DSDL_SENSOR=OFF -DSDL_DIALOG=OFF -DHAVE_DINPUT_H=1)
wanted=$(for p in "${!WINDOWS_DEP_VERSIONS[@]}"; do echo "$p ${WINDOWS_DEP_VERSIONS[$p]}"; done | sort
  echo "libsdl3 options ${sdl_options[*]}")
if [[ -f $prefix/.built && $(cat "$prefix/.built") == "$wanted" ]]; then
  echo "$prefix"
  exit 0
fi
"$project/tools/windows/fetch-sources.sh" >/dev/null
rm -rf "$prefix" "$dir/build"
mkdir -p "$prefix" "$dir/build"
log=$dir/build/build.log
run() { "$@" >>"$log" 2>&1 || { tail -n 40 "$log" >&2; die "failed: $* (log: $log)"; }; }

# hidapi: its own CMake build, the Windows backend only (hid.dll and cfgmgr32.dll are loaded
# by hidapi at run time, so they are not even imports).
run cmake -S "$dir/src/hidapi" -B "$dir/build/hidapi" -G Ninja -Wno-dev \
  -DCMAKE_TOOLCHAIN_FILE="$project/gdextension/cmake/mingw-w64.cmake" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_INSTALL_PREFIX="$prefix" -DBUILD_SHARED_LIBS=OFF -DHIDAPI_WITH_TESTS=OFF \
  -DHIDAPI_BUILD_HIDTEST=OFF
run cmake --build "$dir/build/hidapi" -j 2
run cmake --install "$dir/build/hidapi"

# hidapi.h marks every function __declspec(dllexport) on Windows (for hidapi's own DLL), which
# would export them from our DLL too: the archive's export directives are dropped.
run "$triple-objcopy" --remove-section .drectve "$prefix/lib/libhidapi.a"

# libusb: its release tarball's configure; static, no examples or tests.
mkdir -p "$dir/build/libusb"
(cd "$dir/build/libusb" && run "$dir/src/libusb-1.0/configure" --host="$triple" \
  CC="$triple-gcc-posix" --prefix="$prefix" --enable-static --disable-shared \
  --disable-examples-build --disable-tests-build)
run make -C "$dir/build/libusb" -j 2
run make -C "$dir/build/libusb" install

# SDL 3: its own CMake build, static, with its joystick, gamepad and haptic subsystems and the
# HIDAPI joystick drivers (SDL's own hidapi copy, its symbols renamed), and nothing of audio,
# video, rendering, cameras, sensors, power or dialogs. Its Windows joystick drivers (RawInput,
# Windows.Gaming.Input, XInput, DirectInput) and its DirectInput haptics load what they need at
# run time (xinput1_4.dll, COM's DirectInput 8), so they add no import of a non-Windows DLL.
# SDL's CMake looks for dinput.h only when its DirectX option is on, which it ties to audio or
# video: HAVE_DINPUT_H=1 says MinGW-w64 has it, for the DirectInput joystick and haptic drivers.
# The virtual joystick stays (3.2.10's SDL_joystick.c names its driver even when it is off).
run cmake -S "$dir/src/libsdl3" -B "$dir/build/libsdl3" -G Ninja -Wno-dev \
  -DCMAKE_TOOLCHAIN_FILE="$project/gdextension/cmake/mingw-w64.cmake" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_INSTALL_PREFIX="$prefix" "${sdl_options[@]}"
run cmake --build "$dir/build/libsdl3" -j 2
run cmake --install "$dir/build/libsdl3"

# SDL's hidapi copy renames hidapi's functions (src/hidapi/SDL_hidapi.c) but not the Windows
# helpers hidapi's own library defines too (hid_winapi_get_container_id...): those are made
# local to SDL's archive, so each keeps its own and the two link together.
mapfile -t shared < <(comm -12 \
  <("$triple-nm" -g --defined-only "$prefix/lib/libhidapi.a" | awk 'NF == 3 { print $3 }' | sort -u) \
  <("$triple-nm" -g --defined-only "$prefix/lib/libSDL3.a" | awk 'NF == 3 { print $3 }' | sort -u))
if ((${#shared[@]} > 0)); then
  run "$triple-objcopy" "${shared[@]/#/--localize-symbol=}" "$prefix/lib/libSDL3.a"
fi

# hidapi's CMake names the Windows library libhidapi.a; all three must exist.
for library in "$prefix/lib/libhidapi.a" "$prefix/lib/libusb-1.0.a" "$prefix/lib/libSDL3.a"; do
  [[ -f $library ]] || die "the build left no $library"
done
printf '%s\n' "$wanted" >"$prefix/.built"
echo "$prefix"
