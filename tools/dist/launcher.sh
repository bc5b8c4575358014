#!/bin/sh
# Starts the exported game named after this file (runtime/<name>.x86_64) with the C library
# and the libraries shipped in runtime/, so it needs none of the system's except the GPU
# driver. Arguments are passed to the game (e.g. ./haptic-game --rendering-driver opengl3,
# ./haptic-game -- --autopilot, or ./haptic-pong-server --headless -- --server).
self=$(readlink -f "$0")
here=$(dirname "$self")
name=$(basename "$self")
runtime="$here/runtime"
# The game's libraries are the bundle's: a preload meant for the system's C library must
# not enter (the library path given to the loader already overrides LD_LIBRARY_PATH).
unset LD_PRELOAD
exec "$runtime/$name.loader" --argv0 "$0" --library-path "$runtime/lib" \
	"$runtime/$name.x86_64" "$@"
