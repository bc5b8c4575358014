#!/usr/bin/env bash
# Builds the static hidapi (its Windows backend) and libusb (WinUSB) for Windows x86_64 with
# MinGW-w64 from the sources tools/windows/fetch-sources.sh fetched, into one install prefix,
# .build/windows-deps/prefix (ignored). Rebuilt only when a pinned version changes.
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

wanted=$(for p in "${!WINDOWS_DEP_VERSIONS[@]}"; do echo "$p ${WINDOWS_DEP_VERSIONS[$p]}"; done | sort)
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

# hidapi's CMake names the Windows library libhidapi.a; both must exist.
for library in "$prefix/lib/libhidapi.a" "$prefix/lib/libusb-1.0.a"; do
  [[ -f $library ]] || die "the build left no $library"
done
printf '%s\n' "$wanted" >"$prefix/.built"
echo "$prefix"
