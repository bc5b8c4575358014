#include "dev_tools/falcon/scripted_falcon_device.h"

#include <utility>

namespace haptics::falcon {

std::vector<uint8_t> make_test_firmware_image(size_t p_size, uint32_t p_seed) {
	std::vector<uint8_t> image(p_size);
	uint32_t state = p_seed ? p_seed : 1;
	for (uint8_t &byte : image) {
		state ^= state << 13; // xorshift32
		state ^= state >> 17;
		state ^= state << 5;
		byte = static_cast<uint8_t>(state >> 24);
	}
	return image;
}

FalconDeviceConfig scripted_device_config() {
	FalconDeviceConfig config;
	config.firmware_image = make_test_firmware_image();
	return config;
}

std::unique_ptr<FalconDevice> make_scripted_device(const std::shared_ptr<ScriptedFalcon> &p_model, const FalconDeviceConfig &p_config) {
	std::weak_ptr<ScriptedFalcon> model = p_model;
	UsbTransportOpener opener = [model](std::unique_ptr<usb::UsbTransport> &r_transport) {
		const std::shared_ptr<ScriptedFalcon> alive = model.lock();
		if (!alive) {
			return Status::error(StatusCode::NO_DEVICE, "Novint Falcon not present (the scripted Falcon is gone)");
		}
		return alive->open_transport(r_transport);
	};
	return std::make_unique<FalconDevice>(std::move(opener), p_config);
}

} // namespace haptics::falcon
