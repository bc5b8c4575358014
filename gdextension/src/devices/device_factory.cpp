#include "devices/device_factory.h"

#include <cstdlib>
#include <string_view>

namespace haptics {

namespace {

struct BackendRow {
	std::string_view driver;
	DeviceAvailability (*probe)(const DeviceInfo &p_info);
	Status (*open)(const DeviceInfo &p_info, const DeviceOpenOptions &p_options, std::unique_ptr<HapticDevice> &r_device);
};

DeviceAvailability probe_simulated(const DeviceInfo &p_info) {
	DeviceAvailability availability;
	availability.handled = p_info.backend == BACKEND_SIMULATED;
	availability.openable = availability.handled;
	return availability;
}

// The first row whose probe handles a device drives it; order matters only where two
// backends could claim one device.
constexpr BackendRow BACKENDS[] = {
	{ DRIVER_SIMULATED, probe_simulated, nullptr },
};

} // namespace

bool scripted_devices_enabled() {
	const char *value = std::getenv(SCRIPTED_DEVICES_VARIABLE);
	return value != nullptr && std::string_view(value) == "1";
}

void probe_devices(std::vector<DeviceInfo> &r_devices) {
	for (DeviceInfo &info : r_devices) {
		info.driver.clear();
		info.openable = false;
		info.unavailable_reason = "no force-feedback driver for this device";
		for (const BackendRow &backend : BACKENDS) {
			const DeviceAvailability availability = backend.probe(info);
			if (availability.handled) {
				info.driver = backend.driver;
				info.openable = availability.openable;
				info.unavailable_reason = availability.openable ? std::string() : availability.reason;
				break;
			}
		}
	}
}

DeviceList list_all_devices() {
	DeviceList list = list_devices();
	probe_devices(list.devices);
	return list;
}

Status open_listed_device(const DeviceInfo &p_info, const DeviceOpenOptions &p_options,
		std::unique_ptr<HapticDevice> &r_device) {
	for (const BackendRow &backend : BACKENDS) {
		if (backend.open == nullptr || !backend.probe(p_info).handled) {
			continue;
		}
		return backend.open(p_info, p_options, r_device);
	}
	return Status::error(StatusCode::UNSUPPORTED, "no force-feedback driver for '%s' (%s)", p_info.id.c_str(),
			p_info.model.empty() ? p_info.product.c_str() : p_info.model.c_str());
}

} // namespace haptics
