#include "devices/evdev/evdev_backend.h"

namespace haptics::evdev {

DeviceAvailability probe(const DeviceInfo &p_info, EvdevSyscalls &r_sys) {
	DeviceAvailability availability;
	if (p_info.backend != BACKEND_EVDEV) {
		return availability;
	}
	availability.handled = true;
	if (p_info.path.empty()) {
		availability.reason = "no /dev/input/eventN path for this device";
		return availability;
	}
	const char *path = p_info.path.c_str();
	const int fd = r_sys.open_device(path);
	if (fd < 0) {
		availability.reason = evdev_open_error(fd, path).message();
		return availability;
	}
	EvdevFfFeatures features;
	EvdevOutput output = EvdevOutput::CONSTANT;
	Status status = query_ff_features(r_sys, fd, path, features);
	if (status) {
		status = choose_ff_output(features, path, output);
	}
	r_sys.close(fd);
	if (!status) {
		availability.reason = status.message();
		return availability;
	}
	availability.openable = true;
	return availability;
}

DeviceAvailability probe(const DeviceInfo &p_info) {
	return probe(p_info, *linux_evdev_syscalls());
}

EvdevDeviceConfig device_config_for(const DeviceInfo &p_info) {
	EvdevDeviceConfig config;
	config.path = p_info.path;
	config.model = !p_info.model.empty() ? p_info.model : p_info.product;
	return config;
}

Status open_device(const DeviceInfo &p_info, const std::shared_ptr<EvdevSyscalls> &p_sys,
		std::unique_ptr<HapticDevice> &r_device, const EvdevTakeover &p_takeover) {
	if (p_info.backend != BACKEND_EVDEV) {
		return Status::error(StatusCode::INVALID_ARGUMENT, "device '%s' belongs to backend '%s', not evdev",
				p_info.id.c_str(), p_info.backend.c_str());
	}
	EvdevDeviceConfig config = device_config_for(p_info);
	config.takeover = p_takeover;
	auto device = std::make_unique<EvdevDevice>(p_sys, config);
	const Status opened = device->open();
	if (!opened) {
		return opened;
	}
	r_device = std::move(device);
	return Status::success();
}

Status open_device(const DeviceInfo &p_info, std::unique_ptr<HapticDevice> &r_device, const EvdevTakeover &p_takeover) {
	return open_device(p_info, linux_evdev_syscalls(), r_device, p_takeover);
}

} // namespace haptics::evdev
