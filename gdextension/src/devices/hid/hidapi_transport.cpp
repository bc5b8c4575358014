#include "devices/hid/hidapi_transport.h"

#include "devices/hid/hidapi_open.h"
#include "devices/hid/hidraw_sysfs.h"
#include "devices/hid/report_descriptor.h"

#include <hidapi.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>

namespace haptics::hid {

HidapiTransport::HidapiTransport(std::string p_path) :
		path_(std::move(p_path)) {}

HidapiTransport::~HidapiTransport() {
	close();
}

Status HidapiTransport::open() {
	if (device_) {
		return Status::success();
	}
	const Status opened = open_hidraw_device(path_, "hid-pid", device_);
	if (opened) {
		error_[0] = '\0';
		halted_ = false;
	}
	return opened;
}

void HidapiTransport::close() {
	if (device_) {
		hid_close(device_);
		device_ = nullptr;
	}
}

Status HidapiTransport::report_descriptor(std::vector<uint8_t> &r_bytes) {
	if (device_ && read_open_report_descriptor(device_, path_, r_bytes)) {
		return Status::success();
	}
	// hidapi < 0.14 has no call for it; sysfs has the same bytes and needs no privileges.
	return read_hidraw_report_descriptor(path_, r_bytes);
}

DeviceIo HidapiTransport::failed(const char *p_call, int p_errno) {
	char message[128];
	narrow_hid_text(device_ ? hid_error(device_) : nullptr, std::strerror(p_errno), message, sizeof(message));
	if (p_errno == EPIPE) {
		halted_ = true;
		const int length = std::snprintf(error_, sizeof(error_), "%.24s on %.32s: endpoint stalled (%.32s)", p_call,
				path_.c_str(), message);
		halt_text_length_ = std::min(static_cast<size_t>(std::max(length, 0)), sizeof(error_) - 1);
		std::snprintf(error_ + halt_text_length_, sizeof(error_) - halt_text_length_, "; resetting it");
		return DeviceIo::FAILED;
	}
	std::snprintf(error_, sizeof(error_), "%s on %s: %s", p_call, path_.c_str(), message);
	return hid_device_lost(p_errno, path_, message) ? DeviceIo::DISCONNECTED : DeviceIo::FAILED;
}

bool HidapiTransport::clear_halt() {
	if (!halted_) {
		return false;
	}
	halted_ = false;
	// A STALLed endpoint stays halted until someone clears it, and only a reset reaches it
	// from here (hidraw_sysfs.h). The device starts over, so the game's reconnect opens it
	// again, effects and all.
	const Status reset = reset_usb_device_of(path_);
	std::snprintf(error_ + halt_text_length_, sizeof(error_) - halt_text_length_, "; %.64s",
			reset ? "reset it, reopening" : reset.message());
	return true;
}

DeviceIo HidapiTransport::write_output(std::span<const uint8_t> p_report) {
	if (!device_) {
		return failed("hid_write", EBADF);
	}
	errno = 0;
	const int written = hid_write(device_, p_report.data(), p_report.size());
	if (written < 0) {
		return failed("hid_write", errno);
	}
	return DeviceIo::OK;
}

DeviceIo HidapiTransport::send_feature(std::span<const uint8_t> p_report) {
	if (!device_) {
		return failed("hid_send_feature_report", EBADF);
	}
	errno = 0;
	if (hid_send_feature_report(device_, p_report.data(), p_report.size()) < 0) {
		return failed("hid_send_feature_report", errno);
	}
	return DeviceIo::OK;
}

DeviceIo HidapiTransport::get_feature(std::span<uint8_t> p_buffer, size_t &r_length) {
	r_length = 0;
	if (!device_ || p_buffer.empty()) {
		return failed("hid_get_feature_report", EBADF);
	}
	errno = 0;
	const int length = hid_get_feature_report(device_, p_buffer.data(), p_buffer.size());
	if (length < 0) {
		return failed("hid_get_feature_report", errno);
	}
	r_length = static_cast<size_t>(length);
	return DeviceIo::OK;
}

DeviceIo HidapiTransport::read_input(std::span<uint8_t> p_buffer, size_t &r_length) {
	r_length = 0;
	if (!device_) {
		return failed("hid_read_timeout", EBADF);
	}
	errno = 0;
	const int length = hid_read_timeout(device_, p_buffer.data(), p_buffer.size(), 0);
	if (length < 0) {
		return failed("hid_read_timeout", errno);
	}
	r_length = static_cast<size_t>(length);
	return DeviceIo::OK;
}

} // namespace haptics::hid
