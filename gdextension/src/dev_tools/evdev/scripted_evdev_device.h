#pragma once

// The evdev backend's device class over the software model of the kernel
// (scripted_evdev_kernel.h): for the doctests, the benchmark and development builds' listed
// models.

#include "core/device/device.h"
#include "dev_tools/evdev/scripted_evdev_kernel.h"
#include "devices/evdev/evdev_device.h"

#include <memory>

namespace haptics::evdev {

// An EvdevDevice over p_kernel, NOT yet opened (HapticsSystem::open_device opens it). An
// empty p_config.path means the kernel script's path. The test keeps p_kernel to script
// the stick, unplug it and read what was sent.
std::unique_ptr<HapticDevice> make_scripted_device(const std::shared_ptr<ScriptedEvdevKernel> &p_kernel,
		EvdevDeviceConfig p_config = {});

} // namespace haptics::evdev
