#pragma once

// The Falcon backend's entry points, what device discovery and the binding call:
//
//   probe(info)          which enumerated devices this backend drives (libusb 0403:cb48) and
//                        whether one can be opened now, with the reason the player can act on
//                        (the udev rule; the firmware file);
//   open_device(info)    an opened FalconDevice on the real bus (libusb_transport.h).
// The same device over a software model of the Falcon is a development tool
// (dev_tools/falcon/scripted_falcon_device.h).
//
// The firmware file is the user's (Novint's license forbids shipping it, docs/devices/falcon.md,
// "Loading the firmware"): a path
// passed in, else the HAPTICS_FALCON_FIRMWARE environment variable. probe() cannot know
// whether a Falcon still runs firmware from an earlier session without talking to it, so it
// asks for the file whenever none is set; open_device() only needs it when the Falcon has
// no firmware running.

#include "core/base/status.h"
#include "core/device/device.h"
#include "devices/device_info.h"
#include "devices/falcon/falcon_device.h"

#include <memory>
#include <string>
#include <vector>

namespace haptics::falcon {

inline constexpr const char *FALCON_NO_PERMISSION_REASON =
		"no permission for the Falcon's USB node: install the udev rule (tools/udev, see README Devices)";

// HAPTICS_FALCON_FIRMWARE, or "" when unset.
std::string firmware_path_from_environment();

// Handled for backend "libusb" with VID:PID 0403:cb48. p_firmware_path empty: the
// environment variable.
DeviceAvailability probe(const DeviceInfo &p_info);
DeviceAvailability probe(const DeviceInfo &p_info, const std::string &p_firmware_path);

// Opens the Falcon p_info names (uploading the firmware when it needs it) and starts its I/O.
// r_device is set only on success.
Status open_device(const DeviceInfo &p_info, std::unique_ptr<HapticDevice> &r_device);
Status open_device(const DeviceInfo &p_info, const std::string &p_firmware_path, std::unique_ptr<HapticDevice> &r_device);

} // namespace haptics::falcon
