#include "devices/dualsense/dualsense_hidapi_transport.h"

#include <hidapi.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <cwchar>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

namespace haptics::dualsense {

namespace {

// hidapi's wide text -> our fixed buffer, ASCII kept, anything else '?': no allocation (this
// runs on the I/O thread) and hidapi's texts are English.
void narrow_into(const wchar_t *p_text, const char *p_fallback, char *r_buffer, size_t p_capacity) {
	size_t out = 0;
	if (p_text != nullptr) {
		for (; p_text[out] != L'\0' && out + 1 < p_capacity; ++out) {
			const wchar_t c = p_text[out];
			r_buffer[out] = (c > 0 && c < 0x80) ? static_cast<char>(c) : '?';
		}
	}
	if (out == 0 && p_fallback != nullptr) {
		std::snprintf(r_buffer, p_capacity, "%s", p_fallback);
		return;
	}
	r_buffer[out] = '\0';
}

bool is_disconnect_errno(int p_errno) {
	return p_errno == ENODEV || p_errno == EIO || p_errno == ENXIO || p_errno == ESHUTDOWN || p_errno == EPIPE ||
			p_errno == ENOENT;
}

enum class NodeCheck {
	HIDRAW,
	MISSING,
	NO_PERMISSION,
	NOT_HIDRAW,
};

// hidapi 0.13.1's hid_open_path crashes (SIGSEGV in free) when the path is a character
// device that is not hidraw (seen with /dev/null on this machine), so a path that did not
// come from enumeration is checked first: a character device whose sysfs subsystem is
// "hidraw" (or, without sysfs, whose name starts with "hidraw").
NodeCheck check_node(const char *p_path, int &r_errno) {
	struct stat info {};
	if (::stat(p_path, &info) != 0) {
		r_errno = errno;
		return errno == EACCES || errno == EPERM ? NodeCheck::NO_PERMISSION : NodeCheck::MISSING;
	}
	if (!S_ISCHR(info.st_mode)) {
		return NodeCheck::NOT_HIDRAW;
	}
	char link_path[64];
	std::snprintf(link_path, sizeof(link_path), "/sys/dev/char/%u:%u/subsystem", major(info.st_rdev), minor(info.st_rdev));
	char target[256];
	const ssize_t length = ::readlink(link_path, target, sizeof(target) - 1);
	const char *name = p_path;
	if (length > 0) {
		target[length] = '\0';
		name = target;
	}
	const char *slash = std::strrchr(name, '/');
	const char *base = slash != nullptr ? slash + 1 : name;
	if (length > 0) {
		return std::strcmp(base, "hidraw") == 0 ? NodeCheck::HIDRAW : NodeCheck::NOT_HIDRAW;
	}
	return std::strncmp(base, "hidraw", 6) == 0 ? NodeCheck::HIDRAW : NodeCheck::NOT_HIDRAW;
}

} // namespace

HidapiTransport::HidapiTransport(std::string p_path) :
		path_(std::move(p_path)) {}

HidapiTransport::~HidapiTransport() {
	close();
}

Status HidapiTransport::open() {
	close();
	if (path_.empty()) {
		return Status::error(StatusCode::INVALID_ARGUMENT, "DualSense: empty hidraw path");
	}
	int node_errno = 0;
	switch (check_node(path_.c_str(), node_errno)) {
		case NodeCheck::MISSING:
			return Status::error(StatusCode::NO_DEVICE, "DualSense: no device at '%s' (%s)", path_.c_str(),
					std::strerror(node_errno));
		case NodeCheck::NO_PERMISSION: {
			char reason[224];
			std::snprintf(reason, sizeof(reason), PERMISSION_REASON_FORMAT, path_.c_str());
			return Status::error(StatusCode::DEVICE_ERROR, "DualSense: %s", reason);
		}
		case NodeCheck::NOT_HIDRAW:
			return Status::error(StatusCode::DEVICE_ERROR, "DualSense: '%s' is not a hidraw device node", path_.c_str());
		case NodeCheck::HIDRAW:
			break;
	}
	if (hid_init() != 0) {
		narrow_into(hid_error(nullptr), "unknown error", error_, sizeof(error_));
		return Status::error(StatusCode::DEVICE_ERROR, "DualSense: hidapi cannot initialise (%s)", error_);
	}
	errno = 0;
	device_ = hid_open_path(path_.c_str());
	const int open_errno = errno;
	if (device_ == nullptr) {
		narrow_into(hid_error(nullptr), std::strerror(open_errno), error_, sizeof(error_));
		if (open_errno == EACCES || open_errno == EPERM) {
			char reason[224];
			std::snprintf(reason, sizeof(reason), PERMISSION_REASON_FORMAT, path_.c_str());
			return Status::error(StatusCode::DEVICE_ERROR, "DualSense: %s", reason);
		}
		if (open_errno == ENOENT || open_errno == ENODEV || open_errno == ENXIO) {
			return Status::error(StatusCode::NO_DEVICE, "DualSense: no device at '%s' (%s)", path_.c_str(), error_);
		}
		return Status::error(StatusCode::DEVICE_ERROR, "DualSense: cannot open '%s' (%s)", path_.c_str(), error_);
	}
	if (hid_set_nonblocking(device_, 1) != 0) {
		narrow_into(hid_error(device_), "hid_set_nonblocking failed", error_, sizeof(error_));
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
	narrow_into(device_ != nullptr ? hid_error(device_) : nullptr, p_errno != 0 ? std::strerror(p_errno) : "failed", text,
			sizeof(text));
	std::snprintf(error_, sizeof(error_), "%s: %s", p_call, text);
	const bool gone = is_disconnect_errno(p_errno) || ::access(path_.c_str(), F_OK) != 0 ||
			std::strstr(text, "disconnected") != nullptr;
	return gone ? TransportIo::DISCONNECTED : TransportIo::FAILED;
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
