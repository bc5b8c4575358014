#include "devices/dualsense/dualsense_backend.h"

#include "devices/dualsense/dualsense_hidapi_transport.h"
#include "devices/hid/hidapi_open.h"
#include "devices/hid/hidraw_sysfs.h"

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace haptics::dualsense {

bool is_dualsense(uint16_t p_vendor_id, uint16_t p_product_id, DualSenseModel *r_model) {
	if (p_vendor_id != SONY_VENDOR_ID) {
		return false;
	}
	if (p_product_id != DUALSENSE_PRODUCT_ID && p_product_id != DUALSENSE_EDGE_PRODUCT_ID) {
		return false;
	}
	if (r_model != nullptr) {
		*r_model = p_product_id == DUALSENSE_EDGE_PRODUCT_ID ? DualSenseModel::EDGE : DualSenseModel::DUALSENSE;
	}
	return true;
}

DeviceAvailability availability_for(const DeviceInfo &p_info, int p_access_errno) {
	DeviceAvailability availability;
	if (p_info.backend != BACKEND_HIDAPI || !is_dualsense(p_info.vendor_id, p_info.product_id)) {
		return availability;
	}
	availability.handled = true;
	if (p_info.path.empty()) {
		availability.reason = "no hidraw path for this DualSense";
		return availability;
	}
	if (p_access_errno == 0) {
		availability.openable = true;
		return availability;
	}
	char reason[256];
	if (p_access_errno == EACCES || p_access_errno == EPERM || p_access_errno == EROFS) {
		std::snprintf(reason, sizeof(reason), hid::PERMISSION_REASON_FORMAT, p_info.path.c_str());
	} else if (p_access_errno == ENOENT) {
		std::snprintf(reason, sizeof(reason), "%s is gone: the DualSense was unplugged", p_info.path.c_str());
	} else {
		std::snprintf(reason, sizeof(reason), "cannot open %s: %s", p_info.path.c_str(), std::strerror(p_access_errno));
	}
	availability.reason = reason;
	return availability;
}

DeviceAvailability probe(const DeviceInfo &p_info) {
	return availability_for(p_info, p_info.path.empty() ? 0 : hid::hid_node_access_errno(p_info.path));
}

Status open_device(const DeviceInfo &p_info, std::unique_ptr<HapticDevice> &r_device, const DualSenseConfig &p_config) {
	DualSenseModel model = DualSenseModel::DUALSENSE;
	const DeviceAvailability availability = probe(p_info);
	if (!availability.handled || !is_dualsense(p_info.vendor_id, p_info.product_id, &model)) {
		return Status::error(StatusCode::UNSUPPORTED, "device %04x:%04x on backend '%s' is not a DualSense", p_info.vendor_id,
				p_info.product_id, p_info.backend.c_str());
	}
	if (!availability.openable) {
		const bool gone = !p_info.path.empty() && !hid::hid_node_exists(p_info.path);
		return Status::error(gone ? StatusCode::NO_DEVICE : StatusCode::DEVICE_ERROR, "DualSense: %s",
				availability.reason.c_str());
	}
	auto device = std::make_unique<DualSenseDevice>(std::make_unique<HidapiTransport>(p_info.path), model, p_config);
	const Status opened = device->open();
	if (!opened) {
		return opened;
	}
	r_device = std::move(device);
	return Status::success();
}

} // namespace haptics::dualsense
