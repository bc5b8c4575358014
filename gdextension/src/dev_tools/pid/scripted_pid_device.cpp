#include "dev_tools/pid/scripted_pid_device.h"

#include <utility>

namespace haptics::pid {

std::unique_ptr<HapticDevice> make_scripted_device(std::shared_ptr<ScriptedPidJoystick> p_joystick, const PidDeviceConfig &p_config) {
	if (!p_joystick) {
		p_joystick = std::make_shared<ScriptedPidJoystick>(ScriptedFirmware::AJ);
	}
	const char *name = "Scripted PID joystick (AJ firmware)";
	if (p_joystick->firmware() == ScriptedFirmware::VIRTUAL) {
		name = "Scripted PID joystick (OFB-like)";
	} else if (p_joystick->firmware() == ScriptedFirmware::VIRTUAL_WHEEL) {
		name = "Scripted PID wheel (OFB-like)";
	}
	return std::make_unique<PidDevice>(make_scripted_transport(std::move(p_joystick)), name, p_config);
}

} // namespace haptics::pid
