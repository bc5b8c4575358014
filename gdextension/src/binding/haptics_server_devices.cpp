// HapticsServer's device methods: what is present (the device factory's list), opening and
// closing, what the open device offers, and the hand and cable of devices in software.

#include "binding/haptics_server.h"

#include "binding/conversions.h"
#include "binding/log.h"
#include "core/base/coordinates.h"
#include "system/device_factory.h"

namespace haptics::binding {

namespace {

gd::Dictionary to_dictionary(const DeviceInfo &p_device) {
	gd::Dictionary d;
	d.set("id", p_device.id);
	d.set("backend", p_device.backend);
	d.set("vendor_id", static_cast<int64_t>(p_device.vendor_id));
	d.set("product_id", static_cast<int64_t>(p_device.product_id));
	d.set("path", p_device.path);
	d.set("product", p_device.product);
	d.set("manufacturer", p_device.manufacturer);
	d.set("serial", p_device.serial);
	d.set("usage_page", static_cast<int64_t>(p_device.usage_page));
	d.set("usage", static_cast<int64_t>(p_device.usage));
	d.set("known_haptic", p_device.known_haptic);
	d.set("model", p_device.model);
	d.set("driver", p_device.driver);
	d.set("openable", p_device.openable);
	d.set("unavailable_reason", p_device.unavailable_reason);
	return d;
}

} // namespace

gd::Array HapticsServer::list_devices() {
	const DeviceList found = list_all_devices();
	last_warnings_ = found.warnings;
	gd::Array out;
	for (const DeviceInfo &device : found.devices) {
		out.append(to_dictionary(device).variant());
	}
	return out;
}

gd::Dictionary HapticsServer::get_device(const std::string &p_id) {
	const DeviceList found = list_all_devices();
	last_warnings_ = found.warnings;
	for (const DeviceInfo &device : found.devices) {
		if (device.id == p_id) {
			return to_dictionary(device);
		}
	}
	HAPTICS_ERROR("No device with id '" + p_id + "'; list_devices() shows what is present.");
	return gd::Dictionary();
}

std::string HapticsServer::get_simulated_device_id() const {
	return std::string(SIMULATED_DEVICE_ID);
}

gd::Array HapticsServer::get_device_warnings() const {
	gd::Array out;
	for (const std::string &warning : last_warnings_) {
		out.append(warning);
	}
	return out;
}

bool HapticsServer::open_device(const std::string &p_id) {
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
		const Status status = open_listed_device(device, DeviceOpenOptions{}, opened);
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

void HapticsServer::close_device() {
	system_.close_device();
	device_id_.clear();
}

std::string HapticsServer::get_device_id() const {
	return system_.has_device() ? device_id_ : std::string();
}

std::string HapticsServer::get_device_name() const {
	return system_.device_name();
}

gd::Dictionary HapticsServer::get_device_limits() const {
	return limits_to_dictionary(system_.device_limits());
}

gd::Dictionary HapticsServer::get_device_capabilities() const {
	return system_.has_device() ? capabilities_to_dictionary(system_.device_capabilities()) : gd::Dictionary();
}

gd::Dictionary HapticsServer::get_device_status() const {
	return device_status_to_dictionary(system_.device_status());
}

bool HapticsServer::calibrate() {
	return report("calibrate", system_.calibrate());
}

bool HapticsServer::set_hand_target(gd::Vector2 p_target_m) {
	const Vec3 target = game_to_device_scaled(p_target_m.x, p_target_m.y, 1.0);
	if (!report("set_hand_target", system_.set_hand_target(target))) {
		return false;
	}
	hand_target_ = p_target_m;
	return true;
}

gd::Vector2 HapticsServer::get_hand_target() const {
	return hand_target_;
}

bool HapticsServer::set_simulated_plugged(bool p_plugged) {
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
