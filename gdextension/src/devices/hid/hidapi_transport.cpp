#include "devices/hid/hidapi_transport.h"

#include "devices/hid/hidraw_sysfs.h"
#include "devices/hid/report_descriptor.h"

#include <hidapi.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <cwchar>
#include <unistd.h>

namespace haptics::hid {

namespace {

// hidapi's wide message into a fixed buffer (ASCII; anything else becomes '?').
void narrow(const wchar_t *p_text, char *r_out, size_t p_capacity) {
	size_t i = 0;
	for (; p_text && p_text[i] != L'\0' && i + 1 < p_capacity; ++i) {
		const wchar_t c = p_text[i];
		r_out[i] = c >= 0x20 && c < 0x7F ? static_cast<char>(c) : '?';
	}
	r_out[i] = '\0';
}

bool contains(const char *p_text, const char *p_word) {
	return std::strstr(p_text, p_word) != nullptr;
}

} // namespace

HidapiTransport::HidapiTransport(std::string p_path) :
		path_(std::move(p_path)) {}

HidapiTransport::~HidapiTransport() {
	close();
}

Status HidapiTransport::open() {
	if (device_) {
		return Status::success();
	}
	if (hid_init() != 0) {
		narrow(hid_error(nullptr), error_, sizeof(error_));
		return Status::error(StatusCode::DEVICE_ERROR, "hidapi cannot initialise: %s", error_);
	}
	std::string reason;
	const bool exists = access(path_.c_str(), F_OK) == 0;
	if (!is_hidraw_node(path_, &reason)) {
		open_errno_ = exists ? ENOTTY : ENOENT;
		return Status::error(exists ? StatusCode::DEVICE_ERROR : StatusCode::DEVICE_DISCONNECTED, "cannot open %s", reason.c_str());
	}
	errno = 0;
	device_ = hid_open_path(path_.c_str());
	if (!device_) {
		open_errno_ = errno;
		narrow(hid_error(nullptr), error_, sizeof(error_));
		if (open_errno_ == EACCES || open_errno_ == EPERM) {
			return Status::error(StatusCode::DEVICE_ERROR, "no permission for %s: install the udev rule (tools/udev, see README Devices)",
					path_.c_str());
		}
		return Status::error(open_errno_ == ENOENT || open_errno_ == ENODEV ? StatusCode::DEVICE_DISCONNECTED : StatusCode::DEVICE_ERROR,
				"cannot open %s: %s", path_.c_str(), error_[0] ? error_ : std::strerror(open_errno_));
	}
	open_errno_ = 0;
	error_[0] = '\0';
	return Status::success();
}

void HidapiTransport::close() {
	if (device_) {
		hid_close(device_);
		device_ = nullptr;
	}
}

Status HidapiTransport::report_descriptor(std::vector<uint8_t> &r_bytes) {
#if HID_API_VERSION >= HID_API_MAKE_VERSION(0, 14, 0)
	if (device_) {
		r_bytes.assign(HID_API_MAX_REPORT_DESCRIPTOR_SIZE, 0);
		const int length = hid_get_report_descriptor(device_, r_bytes.data(), r_bytes.size());
		if (length > 0) {
			r_bytes.resize(static_cast<size_t>(length));
			return Status::success();
		}
		r_bytes.clear();
	}
#endif
	// hidapi < 0.14 has no call for it; sysfs has the same bytes and needs no privileges.
	return read_hidraw_report_descriptor(path_, r_bytes);
}

DeviceIo HidapiTransport::failed(const char *p_call, int p_errno) {
	char message[128];
	narrow(device_ ? hid_error(device_) : nullptr, message, sizeof(message));
	std::snprintf(error_, sizeof(error_), "%s on %s: %s", p_call, path_.c_str(),
			message[0] ? message : std::strerror(p_errno));
	// The node disappears with the device; hidapi's read says "disconnected" on POLLHUP.
	const bool gone = p_errno == ENODEV || p_errno == ENXIO || p_errno == ESHUTDOWN || access(path_.c_str(), F_OK) != 0 ||
			contains(message, "isconnected");
	return gone ? DeviceIo::DISCONNECTED : DeviceIo::FAILED;
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
