#include "dev_tools/evdev/scripted_evdev_device.h"

#include <utility>

namespace haptics::evdev {

std::unique_ptr<HapticDevice> make_scripted_device(const std::shared_ptr<ScriptedEvdevKernel> &p_kernel,
		EvdevDeviceConfig p_config) {
	if (p_config.path.empty() && p_kernel) {
		p_config.path = p_kernel->script().path;
	}
	return std::make_unique<EvdevDevice>(p_kernel, std::move(p_config));
}

} // namespace haptics::evdev
