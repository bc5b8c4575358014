#include "godot/haptics_server.h"

#include "devices/device_enumeration.h"
#include "godot/log.h"

namespace haptics::godot {

namespace {

constexpr const char *EXTENSION_VERSION = "0.1.0";

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
	return d;
}

} // namespace

void HapticsServer::bind_methods(gd::ClassBinder<HapticsServer> &r_binder) {
	r_binder.bind_method("list_devices", &HapticsServer::list_devices);
	r_binder.bind_method("get_device", &HapticsServer::get_device, { "id" });
	r_binder.bind_method("get_device_warnings", &HapticsServer::get_device_warnings);
	r_binder.bind_method("get_version", &HapticsServer::get_version);
}

gd::Array HapticsServer::list_devices() {
	const DeviceList found = haptics::list_devices();
	last_warnings_ = found.warnings;
	gd::Array out;
	for (const DeviceInfo &device : found.devices) {
		out.append(to_dictionary(device).variant());
	}
	return out;
}

gd::Dictionary HapticsServer::get_device(const std::string &p_id) {
	const DeviceList found = haptics::list_devices();
	last_warnings_ = found.warnings;
	for (const DeviceInfo &device : found.devices) {
		if (device.id == p_id) {
			return to_dictionary(device);
		}
	}
	HAPTICS_ERROR("No device with id '" + p_id + "'; list_devices() shows what is present.");
	return gd::Dictionary();
}

gd::Array HapticsServer::get_device_warnings() const {
	gd::Array out;
	for (const std::string &warning : last_warnings_) {
		out.append(warning);
	}
	return out;
}

std::string HapticsServer::get_version() const {
	return std::string("haptics ") + EXTENSION_VERSION + " (Godot " +
			std::to_string(gd::api.version_major) + "." + std::to_string(gd::api.version_minor) +
			"." + std::to_string(gd::api.version_patch) + ")";
}

} // namespace haptics::godot
