#!/usr/bin/env bash
# Exports a self-contained Linux x86_64 build (tools/bundle-runtime.sh):
#   tools/export.sh          the game, debug template: .export/linux/haptic-game
#   tools/export.sh server   the dedicated Pong server ("Linux Server" preset), debug
#                            template: .export/linux-server/haptic-pong-server
# Both take the debug template because Debian's 4.6 release template prints an engine
# error for every Container child's internal signal connection whenever a Control leaves a
# container (about 20 lines at each change of screen, 146 at a server's exit; none with the
# debug template, tools/bare/repro-disconnect.sh): a player's and a server's log would be
# full of engine noise hiding real errors. The game sets its window title itself, so the
# debug template's " (DEBUG)" never shows.
# With the project-local engine, its Debian export templates are installed into the
# project's hermetic XDG data folder first; with your own engine, install the matching
# official templates yourself.
set -euo pipefail
cd "$(dirname "$0")/.."
case ${1:-game} in
  game) preset=Linux dir=.export/linux name=haptic-game flavour=debug ;;
  server) preset="Linux Server" dir=.export/linux-server name=haptic-pong-server flavour=debug ;;
  *) echo "usage: tools/export.sh [game|server]" >&2; exit 2 ;;
esac
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

# Every export ships the product library (make build-release: no development tools). The debug
# template loads the library named for debug, which in this project is the development build
# (make build): the server's export gets the product library under that name.
product=addons/haptics/bin/libhaptics.linux.template_release.x86_64.so
[[ -f $product ]] || {
  echo "export: the product library $product is missing; run 'make build-release'" >&2
  exit 1
}
log=.build/export-$name.log
rm -rf "$dir"
mkdir -p "$dir"
tools/godot --headless --path . "--export-$flavour" "$preset" "$dir/$name.x86_64" \
  >"$log" 2>&1 || { tail -n 30 "$log"; exit 1; }
[[ -x $dir/$name.x86_64 ]] || { tail -n 30 "$log"; exit 1; }
shipped=$dir/libhaptics.linux.template_$flavour.x86_64.so
[[ -f $shipped ]] || { echo "export: Godot did not export $shipped" >&2; exit 1; }
cp "$product" "$shipped"
tools/bundle-runtime.sh "$dir" "$name"
