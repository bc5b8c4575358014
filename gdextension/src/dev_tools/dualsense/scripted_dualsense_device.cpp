#include "dev_tools/dualsense/scripted_dualsense_device.h"

#include <utility>

namespace haptics::dualsense {

std::unique_ptr<DualSenseDevice> make_scripted_device(std::shared_ptr<ScriptedDualSense> p_pad, const DualSenseConfig &p_config) {
	const DualSenseModel model = p_pad->options().edge ? DualSenseModel::EDGE : DualSenseModel::DUALSENSE;
	return std::make_unique<DualSenseDevice>(make_scripted_transport(std::move(p_pad)), model, p_config);
}

ScriptedDualSenseSetup make_scripted_device(Bus p_bus, const ScriptedDualSenseOptions &p_options, const DualSenseConfig &p_config) {
	ScriptedDualSenseOptions options = p_options;
	options.bus = p_bus;
	ScriptedDualSenseSetup setup;
	setup.pad = std::make_shared<ScriptedDualSense>(options);
	setup.device = make_scripted_device(setup.pad, p_config);
	return setup;
}

} // namespace haptics::dualsense
