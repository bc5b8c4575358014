#!/usr/bin/env bash
# Lists the DLLs a Windows binary imports (x86_64-w64-mingw32-objdump -p) and fails on any
# outside Windows' own system DLLs: a player's machine has those and nothing else of ours
# (no MinGW runtime such as libstdc++-6.dll, libgcc_s_seh-1.dll or libwinpthread-1.dll).
#   tools/windows/check-imports.sh FILE.dll|FILE.exe
set -euo pipefail
file=${1:?usage: tools/windows/check-imports.sh FILE}
[[ -f $file ]] || { echo "check-imports: no such file: $file" >&2; exit 1; }
# Windows' own DLLs, lower case, present on every Windows 10/11 install.
allowed=(kernel32.dll user32.dll advapi32.dll ole32.dll shell32.dll msvcrt.dll ws2_32.dll
  avrt.dll winmm.dll setupapi.dll cfgmgr32.dll hid.dll bcrypt.dll ntdll.dll)
mapfile -t imports < <(x86_64-w64-mingw32-objdump -p "$file" |
  sed -nE 's/^[[:space:]]*DLL Name: (.*)$/\1/p' | tr '[:upper:]' '[:lower:]' | sort -u)
((${#imports[@]} > 0)) || { echo "check-imports: $file has no import table (not a PE file?)" >&2; exit 1; }
bad=()
for dll in "${imports[@]}"; do
  [[ " ${allowed[*]} " == *" $dll "* ]] || bad+=("$dll")
done
echo "$(basename "$file") ($(stat -c %s "$file") bytes) imports: ${imports[*]}"
if ((${#bad[@]} > 0)); then
  echo "check-imports: $file imports DLLs Windows does not have: ${bad[*]}" >&2
  exit 1
fi
