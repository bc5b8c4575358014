#pragma once

// Finds the force-feedback evdev nodes through sysfs, without opening anything but the
// candidates' probe: /sys/class/input/eventN/device is the input device, whose
// capabilities/ff (evdev_bits.h) says which effects the kernel driver offers. A node is
// listed when that includes FF_CONSTANT (it renders the force) or FF_RUMBLE (it renders the
// impacts as vibration: gamepads, and any FF_PERIODIC device, for which ff-core adds
// FF_RUMBLE to what sysfs shows).
//
// Each DeviceInfo: backend and driver "evdev"; id "evdev:<phys>" (the kernel's physical
// path, e.g. "usb-0000:00:14.0-2/input0": stable while the device stays in the same
// port), else "evdev:<udev's /dev/input/by-path name>", else "evdev:eventN" (not stable
// across replugs: a last resort); path "<dev root>/eventN"; vendor/product
// from device/id; product from device/name; serial from device/uniq; openable and
// unavailable_reason from probe() (evdev_backend.h).

#include "devices/device_info.h"

#include <string>
#include <vector>

namespace haptics::evdev {

inline constexpr const char *EVDEV_SYSFS_ROOT = "/sys/class/input";
inline constexpr const char *EVDEV_DEV_ROOT = "/dev/input";

// Sorted by event number. A missing sysfs root or an unreadable capability becomes a
// warning, never an error. Tests point both roots at a fake tree.
void enumerate_evdev_devices(std::vector<DeviceInfo> &r_devices, std::vector<std::string> &r_warnings,
		const std::string &p_sysfs_root = EVDEV_SYSFS_ROOT, const std::string &p_dev_root = EVDEV_DEV_ROOT);

// The resolved sysfs directory of the HID device the event node belongs to (e.g.
// /sys/devices/.../0003:046D:C294.0001), found by walking up from <root>/<event>/device to
// the first directory whose `subsystem` is hid (or whose name has the HID form
// BBBB:VVVV:PPPP.NNNN); "" when the node is not on HID. /sys/class/hidraw/hidrawN/device
// resolves to the same directory for the hidraw node of the same device, so the lead can
// pair the two without any id field.
std::string evdev_hid_device_sysfs_dir(const std::string &p_sysfs_root, const std::string &p_event_name);

} // namespace haptics::evdev
