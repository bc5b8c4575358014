#pragma once

// From an enumerated device to a rendering one. Every backend registers one row in
// device_factory.cpp: its driver name, a probe (does it drive this device, can it be opened
// now, and if not why) and an open. list_all_devices() is what the game's picker shows:
// every device present with, for each, whether it can be opened and why not.
//
// A build may add device sources of its own at library initialisation (add_device_source):
// development builds add a software model of each backend's hardware this way
// (dev_tools/scripted_backends.h), which the shipped library does not contain.

#include "core/base/status.h"
#include "core/device/device.h"
#include "devices/device_enumeration.h"
#include "devices/device_info.h"
#include "system/device_open.gen.h"

#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace haptics {

// Devices the factory's own backends do not find on a bus: their own backend name
// (DeviceInfo::backend), what they offer now, and how each is probed and opened.
struct DeviceSource {
	std::string_view backend;
	// Appends the devices on offer (possibly none).
	void (*append)(std::vector<DeviceInfo> &r_devices);
	// Fills driver, openable and unavailable_reason of one of its devices.
	void (*probe)(DeviceInfo &r_info);
	Status (*open)(const DeviceInfo &p_info, std::unique_ptr<HapticDevice> &r_device);
};

// At library initialisation, before any listing (game thread); a source added twice (the
// same backend) is kept once.
void add_device_source(const DeviceSource &p_source);
std::span<const DeviceSource> device_sources();

// list_devices() plus the devices only a backend can find (evdev event nodes, an installed
// OpenHaptics runtime) and the added sources' devices, each probed: driver, openable and
// unavailable_reason filled. Same threading and cost rules as list_devices().
DeviceList list_all_devices();

// Fills driver, openable and unavailable_reason of every entry from the backends' probes.
void probe_devices(std::vector<DeviceInfo> &r_devices);

// Opens a device from list_all_devices(). The simulated device is opened by the engine
// itself (HapticsSystem::open_simulated_device), not here.
Status open_listed_device(const DeviceInfo &p_info, const DeviceOpenOptions &p_options,
		std::unique_ptr<HapticDevice> &r_device);

} // namespace haptics
