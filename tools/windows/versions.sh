# Sourced: the Debian source packages the Windows build compiles, pinned (the one place the
# versions are written). Debian 12's, the ones its Linux packages are built from.
# shellcheck disable=SC2034 # read by the scripts that source this file
WINDOWS_DEP_SUITE=bookworm
declare -A WINDOWS_DEP_VERSIONS=([hidapi]=0.13.1-1 [libusb-1.0]=2:1.0.26-1)
