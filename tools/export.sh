#!/usr/bin/env bash
# Exports the Linux x86_64 release build to .export/linux/ and makes it self-contained
# (tools/bundle-runtime.sh: run it as .export/linux/haptic-game). With the project-local engine,
# its Debian export templates are installed into the project's hermetic XDG data folder
# first; with your own engine, install the matching official templates yourself.
set -euo pipefail
cd "$(dirname "$0")/.."
: "${XDG_DATA_HOME:=$PWD/.xdg/data}"
export XDG_DATA_HOME

which=$(tools/godot --which)
version=$(sed -nE 's/^Godot ([0-9]+\.[0-9]+(\.[0-9]+)?\.[a-z0-9]+).*/\1/p' <<<"$which")
[[ -n $version ]] || { echo "export: cannot parse the engine version from '$which'" >&2; exit 1; }
templates="$XDG_DATA_HOME/godot/export_templates/$version"

if [[ ! -f $templates/linux_release.x86_64 ]]; then
  root=.engine/root/usr/bin
  if [[ $which == *"project-local engine"* && -x $root/godot-template-release ]]; then
    mkdir -p "$templates"
    cp "$root/godot-template-release" "$templates/linux_release.x86_64"
    cp "$root/godot-template-debug" "$templates/linux_debug.x86_64"
    echo "$version" >"$templates/version.txt"
  else
    echo "export: no Linux export templates for Godot $version in $templates." >&2
    echo "Install them from the editor (Editor > Manage Export Templates) or the official" \
      "download, then run again." >&2
    exit 1
  fi
fi

[[ -f gdextension/bin/libhaptics.linux.template_release.x86_64.so ]] || {
  echo "export: the release library is missing; run 'make build-release'" >&2
  exit 1
}
rm -rf .export/linux
mkdir -p .export/linux
tools/godot --headless --path . --export-release Linux .export/linux/haptic-game.x86_64 \
  >.build/export.log 2>&1 || { tail -n 30 .build/export.log; exit 1; }
[[ -x .export/linux/haptic-game.x86_64 ]] || { tail -n 30 .build/export.log; exit 1; }
tools/bundle-runtime.sh .export/linux
