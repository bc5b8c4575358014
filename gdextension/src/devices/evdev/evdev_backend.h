#pragma once

// The evdev backend's entry points, for enumeration, the binding and Settings: whether an
// enumerated device is ours and openable (probe) and opening it (open_device). The same
// device over a software model of the kernel is a development tool
// (dev_tools/evdev/scripted_evdev_device.h).

#include "core/base/status.h"
#include "core/device/device.h"
#include "devices/device_info.h"
#include "devices/evdev/evdev_device.h"

#include <memory>
#include <string_view>

namespace haptics::evdev {

// handled when p_info.backend is "evdev". Opens the node O_RDWR and checks it offers
// FF_CONSTANT or FF_RUMBLE, so `reason` says what the player can do: the udev rule / 'input'
// group (EACCES), unplugged (ENOENT), "the kernel driver offers neither constant force nor
// rumble on this device". Closes it again.
DeviceAvailability probe(const DeviceInfo &p_info);
DeviceAvailability probe(const DeviceInfo &p_info, EvdevSyscalls &r_sys);

// The device config enumeration implies: the path, the product name as the model.
EvdevDeviceConfig device_config_for(const DeviceInfo &p_info);

// Makes the device and opens it (EvdevDevice::open() is idempotent, so handing it to
// HapticsSystem::open_device afterwards is fine). r_device is untouched on failure.
Status open_device(const DeviceInfo &p_info, std::unique_ptr<HapticDevice> &r_device,
		const EvdevTakeover &p_takeover = {});
Status open_device(const DeviceInfo &p_info, const std::shared_ptr<EvdevSyscalls> &p_sys,
		std::unique_ptr<HapticDevice> &r_device, const EvdevTakeover &p_takeover = {});

} // namespace haptics::evdev
