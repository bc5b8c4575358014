# Sourced: the Debian source packages the Windows build compiles, pinned (the one place the
# versions are written): "<suite> <version>" per package. hidapi is Debian testing's: 0.14 is
# the first with hid_get_report_descriptor, which on Windows rebuilds a device's report
# descriptor from the parsed form Windows keeps (HID PID devices need it; Debian 12's 0.13.1
# has no such call). libusb is Debian 12's, the one its Linux package is built from.
# shellcheck disable=SC2034 # read by the scripts that source this file
declare -A WINDOWS_DEP_VERSIONS=([hidapi]="forky 0.15.0-2" [libusb-1.0]="bookworm 2:1.0.26-1")
