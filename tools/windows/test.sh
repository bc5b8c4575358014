#!/usr/bin/env bash
# make test-windows: the doctest suite cross-built for Windows (make build-windows) run under
# Wine, then the import check of the Windows libraries. Linux-only tests are the files named
# *_linux.cpp (cmake/platform.cmake leaves them out of the Windows build); they are counted and
# listed from the Linux build's suite (make build), and the counts must add up: every Linux
# test ran under Wine or is Linux-only, plus the Windows-only ones (*_windows.cpp).
# Then each Windows library is loaded by a minimal host under Wine, and its imports checked.
# Wine's prefix is .build/wine (ignored), made on first use. HAPTICS_WINDOWS_BUILD,
# HAPTICS_WINDOWS_ADDON (tools/windows/build.sh), HAPTICS_LINUX_BUILD (the Linux build folder,
# default .build/debug) and HAPTICS_WINEPREFIX point it at a second build in the same tree.
set -euo pipefail
project=$(cd "$(dirname "$0")/../.." && pwd)
cd "$project"
build=${HAPTICS_WINDOWS_BUILD:-.build/windows}
addon=${HAPTICS_WINDOWS_ADDON:-addons/haptics}
exe=$build-debug/haptics_tests.exe
linux_tests=${HAPTICS_LINUX_BUILD:-.build/debug}/haptics_tests
# Bounds: the first boot of a prefix, and the whole suite (about a minute natively).
BOOT_SECONDS=${WINE_BOOT_SECONDS:-300}
SUITE_SECONDS=${WINE_SUITE_SECONDS:-900}
die() { echo "test-windows: $*" >&2; exit 1; }
[[ -x $exe || -f $exe ]] || die "no $exe (make build-windows)"
[[ -x $linux_tests ]] || die "no $linux_tests (make build)"
# Debian's wine64 package puts its loader outside PATH (the wine package adds the wrapper).
wine=$(command -v wine64 || command -v wine || echo /usr/lib/wine/wine64)
[[ -x $wine ]] || die "no wine (package wine64; make deps installs it)"

export WINEPREFIX=${HAPTICS_WINEPREFIX:-$project/.build/wine} WINEDEBUG=-all WINEARCH=win64
# No Mono or Gecko installer dialogs: the suite needs neither.
export WINEDLLOVERRIDES="mscoree,mshtml="
# Stop what this run started: the prefix's wineserver (it lingers a few seconds after the
# last program), and the folder it leaves behind, /tmp/wine-XXXXXX/server-<dev>-<inode> of
# the prefix in hex, which would otherwise pile up one per fresh prefix.
stop_wine() {
  [[ -d $WINEPREFIX ]] || return 0
  local dev inode server_dir
  read -r dev inode < <(stat -c '%d %i' "$WINEPREFIX")
  server_dir=$(printf 'server-%x-%x' "$dev" "$inode")
  timeout 30 "$(dirname "$(readlink -f "$wine")")/wineserver" -k 2>/dev/null || true
  for dir in /tmp/wine-*/"$server_dir"; do
    [[ -d $dir ]] || continue
    rm -rf "$dir"
    rmdir "$(dirname "$dir")" 2>/dev/null || true
  done
}
trap stop_wine EXIT

if [[ ! -f $WINEPREFIX/system.reg ]]; then
  echo "test-windows: making the Wine prefix $WINEPREFIX"
  timeout "$BOOT_SECONDS" "$wine" wineboot --init >/dev/null 2>&1 || die "wineboot failed or took over ${BOOT_SECONDS} s"
fi

# "[doctest] unskipped test cases passing the current filters: N" ends a listing.
count_listed() { sed -nE 's/^\[doctest\] unskipped test cases passing the current filters: ([0-9]+).*/\1/p'; }
names_listed() { sed -nE '/^={20,}$/,/^={20,}$/p' | grep -vE '^={20,}$' || true; }

linux_only_list=$("$linux_tests" --list-test-cases --source-file='*_linux.cpp' --no-colors)
linux_only=$(count_listed <<<"$linux_only_list")
linux_total=$("$linux_tests" --list-test-cases --no-colors | count_listed)
windows_only=$(timeout 120 "$wine" "$exe" --list-test-cases --source-file='*_windows.cpp' --no-colors 2>/dev/null |
  tr -d '\r' | count_listed)

log=$build-debug/wine-tests.log
start=$(date +%s)
status=0
timeout "$SUITE_SECONDS" "$wine" "$exe" --no-colors --duration=false >"$log" 2>&1 || status=$?
tr -d '\r' <"$log" >"$log.txt" && mv "$log.txt" "$log"
summary=$(grep -E '^\[doctest\] test cases:' "$log" | tail -n 1 || true)
if ((status != 0)) || [[ -z $summary ]]; then
  grep -E 'ERROR|FAILED|TEST CASE|\.cpp' "$log" | tail -n 60 >&2 || true
  ((status == 124)) && die "the suite took over ${SUITE_SECONDS} s under Wine (log: $log)"
  die "the suite failed under Wine (exit $status; log: $log)"
fi
ran=$(sed -nE 's/^\[doctest\] test cases: *([0-9]+) \|.*/\1/p' <<<"$summary")
passed=$(sed -nE 's/.*\| *([0-9]+) passed.*/\1/p' <<<"$summary")
echo "test-windows: $summary ($(($(date +%s) - start)) s under Wine)"
echo "test-windows: $ran test cases ran under Wine ($windows_only of them Windows-only), $passed passed;" \
  "$linux_only of the Linux suite's $linux_total are Linux-only and were left out:"
names_listed <<<"$linux_only_list" | sed 's/^/  /'
expected=$((linux_total - linux_only + windows_only))
((ran == expected)) || die "$ran ran under Wine, expected $expected ($linux_total - $linux_only Linux-only + $windows_only Windows-only): a test is missing from one build"
((ran == passed)) || die "$((ran - passed)) test cases did not pass under Wine"
# What SDL (linked into the DLL) finds under Wine: its subsystems and the devices Wine offers it
# (tests/devices/test_sdl_library_windows.cpp; -s prints a passing case's messages).
# None when the build has no SDL backend (HAPTICS_SDL3=OFF).
timeout 120 "$wine" "$exe" --no-colors -s -tc='sdl under windows*' 2>/dev/null | tr -d '\r' |
  sed -nE 's/^.*: MESSAGE: sdl under windows: (.*)$/test-windows: SDL under Wine: \1/p' || true
# Each library loads on Windows' loader (Wine's), and its GDExtension entry point initialises
# and registers its classes against a minimal host (tests_support/load_host).
for flavour in debug release; do
  dll=$addon/bin/libhaptics.windows.template_$flavour.x86_64.dll
  tools/windows/check-imports.sh "$dll"
  out=$(timeout 120 "$wine" "$build-debug/haptics_load_host.exe" "$dll" 2>&1 | tr -d '\r') ||
    { echo "$out" >&2; die "the $flavour library did not load and register under Wine"; }
  # Each class registers as many methods and constants as its class reference documents
  # (doc_classes/, which tests/foundation/test_doc_classes.gd holds to the Linux library as the
  # engine lists it).
  while read -r _ class _ methods constants; do
    doc=gdextension/doc_classes/$class.xml
    [[ -f $doc ]] || die "the $flavour library registered $class, which has no $doc"
    # grep -c prints 0 for a class without constants, and fails: || true.
    want="methods=$(grep -c '<method name=' "$doc" || true) constants=$(grep -c '<constant name=' "$doc" || true)"
    [[ "$methods $constants" == "$want" ]] ||
      die "the $flavour library registered $class with $methods $constants under Wine, its reference documents $want"
  done < <(grep '^class ' <<<"$out")
  echo "test-windows: $(basename "$dll") under Wine: $(grep -E '^(class|docs) ' <<<"$out" | paste -sd';' | sed 's/;/; /g')"
done
