#pragma once

// The OpenHaptics backend's entry points for the device list and the game: whether the
// user's OpenHaptics runtime is there (we never ship it), and a device over it. HD addresses
// devices by configuration name, not by bus, so there is one device to offer when the
// runtime loads: "openhaptics:default" (HD_DEFAULT_DEVICE, the one set up in the Touch's
// driver tool).

#include "core/base/status.h"
#include "core/device/device.h"
#include "devices/device_info.h"
#include "devices/openhaptics/hd_device.h"
#include "devices/openhaptics/hd_runtime.h"

#include <memory>
#include <string_view>

namespace haptics::openhaptics {

inline constexpr std::string_view OPENHAPTICS_DEFAULT_DEVICE_ID = "openhaptics:default";

// Whether the runtime loads (every function we need resolved) and from where; the lead's
// enumeration lists make_default_device_info() when it does. Loads and unloads libHD.
HdRuntimeLocation runtime_location();

// The "openhaptics:default" entry: backend/driver "openhaptics", path = the library that
// loaded (empty when none), openable and the reason from runtime_location().
DeviceInfo make_default_device_info();

// Handled when p_info.backend is "openhaptics". Openable when the runtime loads (from
// p_info.path when set, else the search); else the reason, e.g. "OpenHaptics runtime not
// found (libHD.so): install 3D Systems' OpenHaptics and Touch driver, or set
// HAPTICS_OPENHAPTICS_LIBRARY". Whether a Touch is plugged in shows only at open.
DeviceAvailability probe(const DeviceInfo &p_info);

// Makes and opens the device for p_info (the runtime from p_info.path when set). On error
// r_device is untouched and the Status says why (runtime missing, hdInitDevice failed with
// its HD error, ...). HdDevice::open() is idempotent, so HapticsSystem::open_device may
// open it again.
Status open_device(const DeviceInfo &p_info, std::unique_ptr<HapticDevice> &r_device);

// The same device class over a runtime given by path (the tests' fake libHD), not opened.
std::unique_ptr<HdDevice> make_device_on_runtime(const char *p_library_path, HdDeviceOptions p_options = {});

} // namespace haptics::openhaptics
