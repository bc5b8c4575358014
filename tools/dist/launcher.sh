#!/bin/sh
# Starts Haptic Side-Scroller with the C library and the libraries shipped in runtime/, so it
# needs none of the system's except the GPU driver. Arguments are passed to the game
# (e.g. ./haptic-game --rendering-driver opengl3, or ./haptic-game -- --autopilot).
here=$(dirname "$(readlink -f "$0")")
runtime="$here/runtime"
# The game's libraries are the bundle's: a preload meant for the system's C library must
# not enter (the library path given to the loader already overrides LD_LIBRARY_PATH).
unset LD_PRELOAD
exec "$runtime/haptic-game.loader" --argv0 "$0" --library-path "$runtime/lib" \
	"$runtime/haptic-game.x86_64" "$@"
