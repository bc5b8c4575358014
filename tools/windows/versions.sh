# Sourced: the Debian source packages the Windows build compiles, pinned (the one place the
# versions are written): "<suite> <version>" per package. hidapi is Debian testing's: 0.14 is
# the first with hid_get_report_descriptor, which on Windows rebuilds a device's report
# descriptor from the parsed form Windows keeps (HID PID devices need it; Debian 12's 0.13.1
# has no such call). libusb is Debian 12's, the one its Linux package is built from. SDL 3
# (source package libsdl3) is Debian 13's: testing's 3.4.18+ds-1 (the Linux headers of
# tools/provision-sdl3.sh) is listed in its Sources index but its tarball is not served by the
# archive this project builds from (404), and the backend needs no more than 3.2.0.
# shellcheck disable=SC2034 # read by the scripts that source this file
declare -A WINDOWS_DEP_VERSIONS=([hidapi]="forky 0.15.0-2" [libusb-1.0]="bookworm 2:1.0.26-1"
  [libsdl3]="trixie 3.2.10+ds-1")
