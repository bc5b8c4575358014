// HapticsSystem's device methods: what is present (the device factory's list), opening and
// closing, what the open device offers, and the hand and cable of devices in software.

#include "binding/system_object.h"

#include "binding/log.h"
#include "binding/wire_values.h"
#include "system/device_factory.h"

namespace haptics::binding {

gd::PackedByteArray SystemObject::list_devices() {
	return encode_result(list_all_devices());
}

std::string SystemObject::get_simulated_device_id() const {
	return std::string(SIMULATED_DEVICE_ID);
}

bool SystemObject::open_device(const std::string &p_id) {
	if (p_id == SIMULATED_DEVICE_ID) {
		if (!report("open_device", system_.open_simulated_device())) {
			return false;
		}
		device_id_ = p_id;
		hand_target_ = {};
		return true;
	}
	const DeviceList found = list_all_devices();
	for (const DeviceInfo &device : found.devices) {
		if (device.id != p_id) {
			continue;
		}
		std::unique_ptr<HapticDevice> opened;
		const Status status = open_listed_device(device, open_options_, opened);
		if (!status) {
			HAPTICS_ERROR("open_device: " + std::string(status.message()) + "; the current device stays open.");
			return false;
		}
		if (!report("open_device", system_.open_device(std::move(opened)))) {
			return false;
		}
		device_id_ = p_id;
		hand_target_ = {};
		return true;
	}
	HAPTICS_ERROR("open_device: no device with id '" + p_id + "'; the current device stays open.");
	return false;
}

bool SystemObject::set_device_open_options(const gd::PackedByteArray &p_options) {
	return decode_argument("set_device_open_options", p_options, open_options_);
}

void SystemObject::close_device() {
	system_.close_device();
	device_id_.clear();
}

std::string SystemObject::get_device_id() const {
	return system_.has_device() ? device_id_ : std::string();
}

std::string SystemObject::get_device_name() const {
	return system_.device_name();
}

gd::PackedByteArray SystemObject::get_device_capabilities() const {
	return encode_result(system_.device_capabilities());
}

gd::PackedByteArray SystemObject::get_device_status() const {
	return encode_result(system_.device_status());
}

bool SystemObject::calibrate() {
	return report("calibrate", system_.calibrate());
}

bool SystemObject::set_hand_target(gd::Vector3 p_target_m) {
	const Vec3 target{ p_target_m.x, p_target_m.y, p_target_m.z };
	if (!report("set_hand_target", system_.set_hand_target(target))) {
		return false;
	}
	hand_target_ = p_target_m;
	return true;
}

gd::Vector3 SystemObject::get_hand_target() const {
	return hand_target_;
}

bool SystemObject::set_simulated_plugged(bool p_plugged) {
	// A development model's cable stays unplugged across reopen attempts, like a real one.
	HapticDevice *device = system_.current_device();
	if (SoftwareCable *cable = device ? device->software_cable() : nullptr) {
		cable->set_plugged(p_plugged);
		return true;
	}
	// The kinds of device with such a cable: the simulated one, and the added sources' (the
	// development models, in builds that have them).
	std::string kinds = "simulated";
	for (const DeviceSource &source : device_sources()) {
		kinds += " nor " + std::string(source.backend);
	}
	HAPTICS_ERROR("set_simulated_plugged: the current device is " +
			(device_sources().empty() ? "not " + kinds : "neither " + kinds) + ".");
	return false;
}

} // namespace haptics::binding
