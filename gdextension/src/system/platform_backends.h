#pragma once

// The device backends only some platforms have, one file per platform
// (platform_backends_linux.cpp: the kernel's force-feedback drivers through evdev;
// platform_backends_windows.cpp: none), besides the backends every platform builds
// (device_factory.cpp). Which files a platform compiles is decided in cmake/platform.cmake.

#include "core/base/status.h"
#include "core/device/device.h"
#include "devices/device_enumeration.h"
#include "devices/device_info.h"

#include <memory>
#include <span>
#include <string_view>

namespace haptics {

struct DeviceOpenOptions;

// One backend: its driver name, its probe (does it drive this device, can it be opened now,
// and if not why) and its open (null for the simulated device, which the engine opens).
struct BackendRow {
	std::string_view driver;
	DeviceAvailability (*probe)(const DeviceInfo &p_info);
	Status (*open)(const DeviceInfo &p_info, const DeviceOpenOptions &p_options, std::unique_ptr<HapticDevice> &r_device);
};

// This platform's own backends, probed after the common ones.
std::span<const BackendRow> platform_backends();

// Appends the devices only this platform's backends find (not on hidapi's or libusb's bus).
void append_platform_devices(DeviceList &r_list);

} // namespace haptics
