#!/bin/sh
# Starts the exported game named after this file (runtime/<name>.x86_64) with the C library
# and the libraries shipped in runtime/, so it needs none of the system's except the GPU
# driver. Arguments are passed to the game (e.g. ./haptic-game --rendering-driver opengl3,
# ./haptic-game --headless -- --system-check, or ./haptic-pong-server --headless -- --server).
self=$(readlink -f "$0")
here=$(dirname "$self")
name=$(basename "$self")
runtime="$here/runtime"
# The oldest system C library whose graphics driver can live beside the shipped one. Before
# glibc 2.34, libdl was a library of its own: a driver built for such a system (Debian 11's
# Mesa links libdl.so.2) makes the loader take the system's copy, which needs private symbols
# of its own libc (_dl_catch_error, _dl_sym... GLIBC_PRIVATE) that the shipped one lacks; the
# engine then blames the video driver. Headless runs load no driver and work there too.
oldest_glibc_minor=34

windowed=yes
for arg in "$@"; do
	case $arg in
	--headless | --version | --help | -h) windowed=no ;;
	--) break ;;
	esac
done
if [ "$windowed" = yes ] && [ -z "${HAPTICS_SKIP_SYSTEM_CHECK:-}" ]; then
	system=$(getconf GNU_LIBC_VERSION 2>/dev/null) || system=""
	version=${system#glibc }
	minor=${version#2.}
	minor=${minor%%.*}
	case $version in
	2.*) ;;
	*) minor="" ;;
	esac
	case $minor in
	'' | *[!0-9]*) ;;
	*)
		if [ "$minor" -lt "$oldest_glibc_minor" ]; then
			cat >&2 <<EOF
$name: this system's C library is glibc $version, older than 2.$oldest_glibc_minor.
The game ships its own, newer C library, but the graphics driver (OpenGL: Mesa or the
vendor's) comes from the system and is built for glibc $version: it links that version's
own libdl, which needs private parts of glibc $version that the shipped C library does not
have, so no OpenGL context can be made (the engine would blame the video driver). Your
video driver is not at fault: windowed play needs a system with glibc 2.$oldest_glibc_minor or
newer (Debian 12, Ubuntu 22.04, Fedora 35 or newer). Without a window,
'$name --headless' runs here.
(HAPTICS_SKIP_SYSTEM_CHECK=1 starts the window anyway.)
EOF
			exit 1
		fi
		;;
	esac
fi

# The game's libraries are the bundle's: a preload meant for the system's C library must
# not enter (the library path given to the loader already overrides LD_LIBRARY_PATH).
unset LD_PRELOAD
libs="$runtime/lib"
# The GPU driver's libraries that the engine links at load time (libgbm, through SDL) are
# the system's; on a system without them (a server, a container) the shipped copies in
# runtime/lib-fallback stand in. The bundled loader's listing resolves them exactly as the
# start will, and fails when one is missing (cheap: docs/supported-systems.md).
if [ -d "$runtime/lib-fallback" ] &&
	! "$runtime/$name.loader" --library-path "$libs" --list "$runtime/$name.x86_64" >/dev/null 2>&1; then
	libs="$libs:$runtime/lib-fallback"
fi
# A system without fontconfig's configuration (a server, a container) gets an empty one: the
# game's fonts are in its pack, and the shipped fontconfig would print an error at each start.
[ -e /etc/fonts/fonts.conf ] || [ -n "${FONTCONFIG_FILE:-}" ] || export FONTCONFIG_FILE="$runtime/fonts.conf"
exec "$runtime/$name.loader" --argv0 "$0" --library-path "$libs" \
	"$runtime/$name.x86_64" "$@"
