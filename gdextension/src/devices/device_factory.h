#pragma once

// From an enumerated device to a rendering one. Every backend registers one row in
// device_factory.cpp: its driver name, a probe (does it drive this device, can it be opened
// now, and if not why) and an open. list_all_devices() is what the game's picker shows:
// every device present with, for each, whether it can be opened and why not.
//
// Scripted devices ("scripted:<driver>": each backend's protocol over its scripted
// transport, a software model of the hardware) are listed only when the environment
// variable HAPTICS_SCRIPTED_DEVICES=1, for the headless tests and for trying a backend's
// code path without its hardware. Their stick or stylus follows the simulated hand target.

#include "core/status.h"
#include "devices/device.h"
#include "devices/device_enumeration.h"

#include <memory>
#include <string>

namespace haptics {

inline constexpr std::string_view SCRIPTED_ID_PREFIX = "scripted:";
inline constexpr const char *SCRIPTED_DEVICES_VARIABLE = "HAPTICS_SCRIPTED_DEVICES";

// Settings the player gives for devices that need something from their own install.
struct DeviceOpenOptions {
	// Novint's firmware image for the Falcon (not ours to ship); "" = $HAPTICS_FALCON_FIRMWARE.
	std::string falcon_firmware_path;
};

// list_devices() plus the devices only a backend can find (evdev event nodes, an installed
// OpenHaptics runtime, scripted devices when enabled), each probed: driver, openable and
// unavailable_reason filled. Same threading and cost rules as list_devices().
DeviceList list_all_devices();

// Fills driver, openable and unavailable_reason of every entry from the backends' probes.
void probe_devices(std::vector<DeviceInfo> &r_devices);

// Opens a device from list_all_devices(). The simulated device is opened by the engine
// itself (HapticsEngine::open_simulated_device), not here.
Status open_listed_device(const DeviceInfo &p_info, const DeviceOpenOptions &p_options,
		std::unique_ptr<HapticDevice> &r_device);

bool scripted_devices_enabled();

} // namespace haptics
