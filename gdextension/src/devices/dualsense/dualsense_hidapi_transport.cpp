#include "devices/dualsense/dualsense_hidapi_transport.h"

#include "devices/hid/hidapi_open.h"

#include <hidapi.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace haptics::dualsense {

HidapiTransport::HidapiTransport(std::string p_path) :
		path_(std::move(p_path)) {}

HidapiTransport::~HidapiTransport() {
	close();
}

Status HidapiTransport::open() {
	close();
	const Status opened = hid::open_hidraw_device(path_, "DualSense", device_);
	if (!opened) {
		return opened;
	}
	if (hid_set_nonblocking(device_, 1) != 0) {
		hid::narrow_hid_text(hid_error(device_), "hid_set_nonblocking failed", error_, sizeof(error_));
		close();
		return Status::error(StatusCode::DEVICE_ERROR, "DualSense: cannot make '%s' non-blocking (%s)", path_.c_str(), error_);
	}
	bus_ = Bus::UNKNOWN;
#if defined(HID_API_VERSION) && HID_API_VERSION >= HID_API_MAKE_VERSION(0, 13, 0)
	if (const hid_device_info *info = hid_get_device_info(device_)) {
		bus_ = info->bus_type == HID_API_BUS_USB		  ? Bus::USB
				: info->bus_type == HID_API_BUS_BLUETOOTH ? Bus::BLUETOOTH
														  : Bus::UNKNOWN;
	}
#endif
	error_[0] = '\0';
	return Status::success();
}

void HidapiTransport::close() {
	if (device_ != nullptr) {
		hid_close(device_);
		device_ = nullptr;
	}
}

TransportIo HidapiTransport::fail(const char *p_call, int p_errno) {
	char text[128];
	hid::narrow_hid_text(device_ != nullptr ? hid_error(device_) : nullptr, p_errno != 0 ? std::strerror(p_errno) : "failed", text,
			sizeof(text));
	std::snprintf(error_, sizeof(error_), "%s: %s", p_call, text);
	return hid::hid_device_lost(p_errno, path_, text) ? TransportIo::DISCONNECTED : TransportIo::FAILED;
}

TransportIo HidapiTransport::write_output(const uint8_t *p_report, size_t p_size) {
	if (device_ == nullptr) {
		std::snprintf(error_, sizeof(error_), "hid_write: device not open");
		return TransportIo::FAILED;
	}
	errno = 0;
	const int written = hid_write(device_, p_report, p_size);
	if (written < 0) {
		return fail("hid_write", errno);
	}
	if (static_cast<size_t>(written) != p_size) {
		std::snprintf(error_, sizeof(error_), "hid_write: short write (%d of %zu bytes)", written, p_size);
		return TransportIo::FAILED;
	}
	return TransportIo::OK;
}

TransportIo HidapiTransport::read_input(uint8_t *r_buffer, size_t p_capacity, size_t &r_size, int p_timeout_ms) {
	r_size = 0;
	if (device_ == nullptr) {
		std::snprintf(error_, sizeof(error_), "hid_read: device not open");
		return TransportIo::FAILED;
	}
	errno = 0;
	const int read = hid_read_timeout(device_, r_buffer, p_capacity, p_timeout_ms);
	if (read < 0) {
		return fail("hid_read", errno);
	}
	r_size = static_cast<size_t>(read);
	return read == 0 ? TransportIo::NO_DATA : TransportIo::OK;
}

TransportIo HidapiTransport::get_feature(uint8_t p_report_id, uint8_t *r_buffer, size_t p_capacity, size_t &r_size) {
	r_size = 0;
	if (device_ == nullptr || p_capacity == 0) {
		std::snprintf(error_, sizeof(error_), "hid_get_feature_report: device not open");
		return TransportIo::FAILED;
	}
	r_buffer[0] = p_report_id;
	errno = 0;
	const int read = hid_get_feature_report(device_, r_buffer, p_capacity);
	if (read < 0) {
		return fail("hid_get_feature_report", errno);
	}
	r_size = static_cast<size_t>(read);
	return TransportIo::OK;
}

} // namespace haptics::dualsense
