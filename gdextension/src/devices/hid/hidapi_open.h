#pragma once

// What both hidapi transports (the PID stick's and the DualSense's) need from hidapi besides
// the report calls: opening a hidraw node without ever handing hidapi anything else, a
// reason for each failure the player can act on, and telling an unplug from another error.

#include "core/base/status.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

struct hid_device_;

namespace haptics::hid {

// printf format, one %s: the path. The systemd uaccess rule covers input joysticks, not
// hidraw (docs/devices/hid.md, "Permissions"), so this is the usual first failure.
inline constexpr const char *PERMISSION_REASON_FORMAT =
		"no permission for %s: install the udev rule (tools/udev, see README Devices)";

// hidapi's wide text into a fixed buffer: ASCII kept, anything else '?', p_fallback when the
// text is null or empty. No allocation: I/O threads call it on their failure paths.
void narrow_hid_text(const wchar_t *p_text, const char *p_fallback, char *r_out, size_t p_capacity);

// hid_init, then hid_open_path once p_path is known to be a hidraw node (is_hidraw_node:
// hidapi 0.13.1 crashes on other character devices). On failure r_device stays null and the
// Status, prefixed with p_label ("DualSense", "hid-pid"), is NO_DEVICE when nothing is at
// p_path, DEVICE_ERROR otherwise (no permission, with the udev hint; not a hidraw node;
// hidapi's own error).
Status open_hidraw_device(const std::string &p_path, const char *p_label, hid_device_ *&r_device);

// An open device's report descriptor through hid_get_report_descriptor (hidapi 0.14+, which
// on Windows rebuilds it from the parsed form Windows keeps). UNSUPPORTED with an older
// hidapi (Debian 12's 0.13.1, where sysfs has the bytes); DEVICE_ERROR naming p_path and
// hidapi's reason when the call fails. r_bytes is empty unless it succeeds.
Status read_open_report_descriptor(hid_device_ *p_device, const std::string &p_path, std::vector<uint8_t> &r_bytes);

// After a failed hidapi call: whether the device is gone (errno ENODEV, EIO, ENXIO, ESHUTDOWN,
// EPIPE or ENOENT, the node vanished from /dev, or hidapi's text says "disconnected", as its
// hidraw read does on POLLHUP) rather than failing while present.
bool hid_device_lost(int p_errno, const std::string &p_path, const char *p_hid_text);

} // namespace haptics::hid
