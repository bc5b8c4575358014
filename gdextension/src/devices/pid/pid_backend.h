#pragma once

// Entry points of the HID PID force-feedback backend (driver "hid-pid"), for enumeration,
// the binding and the Settings picker.
//
// Which devices: hidapi devices whose top-level collection is on the PID page (0x0F), and
// those whose report descriptor (read from sysfs, no privileges needed) holds a usable PID
// layout although the top level is a joystick: AJ-based sticks nest every PID collection
// inside their Joystick application, so hidapi reports them as usage page 0x01.

#include "core/base/status.h"
#include "core/device/device.h"
#include "devices/device_info.h"
#include "devices/pid/pid_device.h"

#include <memory>
#include <string>
#include <string_view>

namespace haptics::pid {

// Whether this backend drives p_info and whether it can be opened now; if not, why, in one
// sentence a player can act on (the udev rule, the kernel's evdev entry, ...). It opens the
// device briefly (hid_open_path) to find out.
DeviceAvailability probe(const DeviceInfo &p_info);
// The same, reading sysfs under p_sysfs_root instead of /sys (tests use a fake tree).
DeviceAvailability probe_with_sysfs(const DeviceInfo &p_info, const std::string &p_sysfs_root);

// A PidDevice over hidapi for p_info.path; the engine opens it (HapticDevice::open).
Status open_device(const DeviceInfo &p_info, std::unique_ptr<HapticDevice> &r_device, const PidDeviceConfig &p_config = {});

} // namespace haptics::pid
