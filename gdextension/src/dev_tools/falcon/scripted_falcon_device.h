#pragma once

// The Falcon backend's device class over the software model of the hardware
// (scripted_falcon.h): for the doctests, the benchmark and development builds' listed
// models.

#include "dev_tools/falcon/scripted_falcon.h"
#include "devices/falcon/falcon_device.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace haptics::falcon {

// A synthetic image for scripted uploads: deterministic pseudo-random bytes, NOT Novint's
// firmware (which the model never needs: it only echoes and then acts as the firmware).
std::vector<uint8_t> make_test_firmware_image(size_t p_size = 7914, uint32_t p_seed = 1);
// The scripted device's defaults: the synthetic image above, no file.
FalconDeviceConfig scripted_device_config();
// Not opened yet (HapticsSystem::open_device opens it). p_model must be held by a shared_ptr
// (ScriptedFalcon hands out transports that share it).
std::unique_ptr<FalconDevice> make_scripted_device(const std::shared_ptr<ScriptedFalcon> &p_model,
		const FalconDeviceConfig &p_config = scripted_device_config());

} // namespace haptics::falcon
