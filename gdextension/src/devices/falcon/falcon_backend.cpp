#include "devices/falcon/falcon_backend.h"

#include "devices/falcon/falcon_ftdi.h"
#include "devices/usb/libusb_transport.h"

#include <cstdlib>

namespace haptics::falcon {

namespace {

bool is_falcon(const DeviceInfo &p_info) {
	return p_info.backend == BACKEND_LIBUSB && p_info.vendor_id == FALCON_VENDOR_ID && p_info.product_id == FALCON_PRODUCT_ID;
}

usb::LibusbOpenRequest request_for(const DeviceInfo &p_info) {
	usb::LibusbOpenRequest request;
	request.path = p_info.path;
	request.vendor_id = FALCON_VENDOR_ID;
	request.product_id = FALCON_PRODUCT_ID;
	request.interface_number = FALCON_INTERFACE;
	request.label = FALCON_MODEL_NAME;
	return request;
}

} // namespace

std::string firmware_path_from_environment() {
	const char *path = std::getenv(FIRMWARE_ENV_VAR);
	return path ? std::string(path) : std::string();
}

DeviceAvailability probe(const DeviceInfo &p_info) {
	return probe(p_info, firmware_path_from_environment());
}

DeviceAvailability probe(const DeviceInfo &p_info, const std::string &p_firmware_path) {
	DeviceAvailability availability;
	if (!is_falcon(p_info)) {
		return availability;
	}
	availability.handled = true;
	usb::UsbResult result = usb::UsbResult::OK;
	const Status access = usb::LibusbTransport::check_access(request_for(p_info), &result);
	if (!access) {
		availability.reason = result == usb::UsbResult::ACCESS ? FALCON_NO_PERMISSION_REASON : access.message();
		return availability;
	}
	std::vector<uint8_t> image;
	const Status firmware = read_firmware_file(p_firmware_path.empty() ? firmware_path_from_environment() : p_firmware_path, image);
	if (!firmware) {
		availability.reason = firmware.message();
		return availability;
	}
	availability.openable = true;
	return availability;
}

Status open_device(const DeviceInfo &p_info, std::unique_ptr<HapticDevice> &r_device) {
	return open_device(p_info, firmware_path_from_environment(), r_device);
}

Status open_device(const DeviceInfo &p_info, const std::string &p_firmware_path, std::unique_ptr<HapticDevice> &r_device) {
	if (!is_falcon(p_info)) {
		return Status::error(StatusCode::INVALID_ARGUMENT, "device '%.80s' (%.16s %04x:%04x) is not a Novint Falcon (libusb 0403:cb48)",
				p_info.id.c_str(), p_info.backend.c_str(), p_info.vendor_id, p_info.product_id);
	}
	FalconDeviceConfig config;
	config.firmware_path = p_firmware_path.empty() ? firmware_path_from_environment() : p_firmware_path;
	const usb::LibusbOpenRequest request = request_for(p_info);
	UsbTransportOpener opener = [request](std::unique_ptr<usb::UsbTransport> &r_transport) {
		std::unique_ptr<usb::LibusbTransport> transport;
		usb::UsbResult result = usb::UsbResult::OK;
		const Status opened = usb::LibusbTransport::open(request, transport, &result);
		if (!opened) {
			if (result == usb::UsbResult::ACCESS) {
				return Status::error(StatusCode::DEVICE_ERROR, "%s (LIBUSB_ERROR_ACCESS)", FALCON_NO_PERMISSION_REASON);
			}
			return opened;
		}
		r_transport = std::move(transport);
		return Status::success();
	};
	auto device = std::make_unique<FalconDevice>(std::move(opener), std::move(config));
	const Status opened = device->open();
	if (!opened) {
		return opened;
	}
	r_device = std::move(device);
	return Status::success();
}

} // namespace haptics::falcon
