#include "devices/openhaptics/openhaptics_backend.h"

#include <utility>

namespace haptics::openhaptics {

HdRuntimeLocation runtime_location() {
	return locate_hd_runtime(nullptr);
}

DeviceInfo make_default_device_info() {
	const HdRuntimeLocation location = runtime_location();
	DeviceInfo info;
	info.id = OPENHAPTICS_DEFAULT_DEVICE_ID;
	info.backend = BACKEND_OPENHAPTICS;
	info.driver = DRIVER_OPENHAPTICS;
	info.path = location.path;
	info.model = "OpenHaptics device (Touch / Phantom)";
	info.product = "OpenHaptics default device";
	info.manufacturer = "3D Systems";
	info.known_haptic = true;
	info.openable = location.loadable;
	info.unavailable_reason = location.reason;
	return info;
}

DeviceAvailability probe(const DeviceInfo &p_info) {
	DeviceAvailability availability;
	availability.handled = p_info.backend == BACKEND_OPENHAPTICS;
	if (!availability.handled) {
		return availability;
	}
	const HdRuntimeLocation location = locate_hd_runtime(p_info.path.c_str());
	availability.openable = location.loadable;
	availability.reason = location.reason;
	return availability;
}

Status open_device(const DeviceInfo &p_info, std::unique_ptr<HapticDevice> &r_device) {
	if (p_info.backend != BACKEND_OPENHAPTICS) {
		return Status::error(StatusCode::INVALID_ARGUMENT, "device '%s': backend '%s' is not openhaptics",
				p_info.id.c_str(), p_info.backend.c_str());
	}
	HdDeviceOptions options;
	options.library_path = p_info.path;
	auto device = std::make_unique<HdDevice>(std::move(options));
	const Status opened = device->open();
	if (!opened) {
		return opened;
	}
	r_device = std::move(device);
	return Status::success();
}

std::unique_ptr<HdDevice> make_device_on_runtime(const char *p_library_path, HdDeviceOptions p_options) {
	p_options.library_path = p_library_path != nullptr ? p_library_path : "";
	return std::make_unique<HdDevice>(std::move(p_options));
}

} // namespace haptics::openhaptics
