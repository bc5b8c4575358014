#pragma once

// The DualSense backend's device class over the software model of the pad
// (scripted_dualsense.h): for the doctests, the benchmark and development builds' listed
// models.

#include "dev_tools/dualsense/scripted_dualsense.h"
#include "devices/dualsense/dualsense_device.h"

#include <memory>

namespace haptics::dualsense {

// A DualSense device over p_pad (not opened; the engine opens it). The pad's options give
// the link (USB or Bluetooth) and model (DualSense or Edge).
std::unique_ptr<DualSenseDevice> make_scripted_device(std::shared_ptr<ScriptedDualSense> p_pad,
		const DualSenseConfig &p_config = {});

// Convenience: a new scripted pad on p_bus and a device over it.
struct ScriptedDualSenseSetup {
	std::shared_ptr<ScriptedDualSense> pad;
	std::unique_ptr<DualSenseDevice> device;
};
ScriptedDualSenseSetup make_scripted_device(Bus p_bus, const ScriptedDualSenseOptions &p_options = {},
		const DualSenseConfig &p_config = {});

} // namespace haptics::dualsense
