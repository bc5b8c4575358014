#include "devices/pid/pid_backend.h"

#include "devices/hid/hidapi_transport.h"
#include "devices/hid/hidraw_sysfs.h"
#include "devices/pid/pid_usages.h"

#include <string>
#include <vector>

namespace haptics::pid {

namespace {

std::string display_name(const DeviceInfo &p_info) {
	if (!p_info.product.empty()) {
		return p_info.product;
	}
	return p_info.model.empty() ? std::string("HID PID force-feedback device") : p_info.model;
}

} // namespace

DeviceAvailability probe(const DeviceInfo &p_info) {
	return probe_with_sysfs(p_info, "/sys");
}

DeviceAvailability probe_with_sysfs(const DeviceInfo &p_info, const std::string &p_sysfs_root) {
	DeviceAvailability availability;
	if (p_info.backend != BACKEND_HIDAPI || p_info.path.empty()) {
		return availability;
	}
	std::vector<uint8_t> descriptor;
	const bool have_descriptor = hid::read_hidraw_report_descriptor(p_info.path, descriptor, p_sysfs_root).ok();
	Status layout_status;
	const bool pid_layout = have_descriptor && has_pid_layout(descriptor, &layout_status);
	if (p_info.usage_page != USAGE_PAGE_PID && !pid_layout) {
		return availability;
	}
	availability.handled = true;
	if (hid::kernel_ff_bound(p_info.path, p_sysfs_root)) {
		availability.reason = "the kernel's force-feedback driver owns it: use its evdev entry";
		return availability;
	}
	if (have_descriptor && !pid_layout) {
		availability.reason = std::string("its force-feedback reports are not usable: ") + layout_status.message();
		return availability;
	}
	hid::HidapiTransport transport(p_info.path);
	const Status opened = transport.open();
	if (!opened) {
		availability.reason = opened.message();
		return availability;
	}
	transport.close();
	availability.openable = true;
	return availability;
}

Status open_device(const DeviceInfo &p_info, std::unique_ptr<HapticDevice> &r_device, const PidDeviceConfig &p_config) {
	if (p_info.backend != BACKEND_HIDAPI || p_info.path.empty()) {
		return Status::error(StatusCode::INVALID_ARGUMENT, "hid-pid: device '%s' is not a hidapi device with a path",
				p_info.id.c_str());
	}
	const Status valid = validate_pid_device_config(p_config);
	if (!valid) {
		return valid;
	}
	r_device = std::make_unique<PidDevice>(std::make_unique<hid::HidapiTransport>(p_info.path), display_name(p_info), p_config);
	return Status::success();
}

} // namespace haptics::pid
