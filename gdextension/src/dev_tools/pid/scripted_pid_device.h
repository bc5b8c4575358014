#pragma once

// The HID PID backend's device class over the software model of a joystick
// (scripted_pid_joystick.h): for the doctests, the benchmark and development builds' listed
// models.

#include "core/device/device.h"
#include "dev_tools/pid/scripted_pid_joystick.h"
#include "devices/pid/pid_device.h"

#include <memory>

namespace haptics::pid {

// The same device class over a scripted joystick (AJ firmware unless p_joystick says
// otherwise); keep p_joystick to script and inspect it.
std::unique_ptr<HapticDevice> make_scripted_device(std::shared_ptr<ScriptedPidJoystick> p_joystick = {},
		const PidDeviceConfig &p_config = {});

} // namespace haptics::pid
