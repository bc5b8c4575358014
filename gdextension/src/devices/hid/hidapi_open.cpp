#include "devices/hid/hidapi_open.h"

#include "devices/hid/hidraw_sysfs.h"

#include <hidapi.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <cwchar>
#include <utility>

namespace haptics::hid {

void narrow_hid_text(const wchar_t *p_text, const char *p_fallback, char *r_out, size_t p_capacity) {
	if (p_capacity == 0) {
		return;
	}
	size_t out = 0;
	for (; p_text != nullptr && p_text[out] != L'\0' && out + 1 < p_capacity; ++out) {
		const wchar_t c = p_text[out];
		r_out[out] = c >= 0x20 && c < 0x7F ? static_cast<char>(c) : '?';
	}
	if (out == 0 && p_fallback != nullptr) {
		std::snprintf(r_out, p_capacity, "%s", p_fallback);
		return;
	}
	r_out[out] = '\0';
}

Status open_hidraw_device(const std::string &p_path, const char *p_label, hid_device_ *&r_device) {
	r_device = nullptr;
	if (p_path.empty()) {
		return Status::error(StatusCode::INVALID_ARGUMENT, "%s: empty hidraw path", p_label);
	}
	char reason[224];
	if (!hid_node_exists(p_path)) {
		return Status::error(StatusCode::NO_DEVICE, "%s: no device at '%s' (%s)", p_label, p_path.c_str(),
				std::strerror(errno));
	}
	if (!is_hidraw_node(p_path)) {
		return Status::error(StatusCode::DEVICE_ERROR, "%s: '%s' is not a hidraw device node", p_label, p_path.c_str());
	}
	char text[160];
	if (hid_init() != 0) {
		narrow_hid_text(hid_error(nullptr), "unknown error", text, sizeof(text));
		return Status::error(StatusCode::DEVICE_ERROR, "%s: hidapi cannot initialise (%s)", p_label, text);
	}
	errno = 0;
	r_device = hid_open_path(p_path.c_str());
	if (r_device != nullptr) {
		return Status::success();
	}
	const int open_errno = errno;
	narrow_hid_text(hid_error(nullptr), std::strerror(open_errno), text, sizeof(text));
	if (open_errno == EACCES || open_errno == EPERM) {
		std::snprintf(reason, sizeof(reason), PERMISSION_REASON_FORMAT, p_path.c_str());
		return Status::error(StatusCode::DEVICE_ERROR, "%s: %s", p_label, reason);
	}
	if (open_errno == ENOENT || open_errno == ENODEV || open_errno == ENXIO) {
		return Status::error(StatusCode::NO_DEVICE, "%s: no device at '%s' (%s)", p_label, p_path.c_str(), text);
	}
	return Status::error(StatusCode::DEVICE_ERROR, "%s: cannot open '%s' (%s)", p_label, p_path.c_str(), text);
}

Status read_open_report_descriptor(hid_device_ *p_device, const std::string &p_path, std::vector<uint8_t> &r_bytes) {
	r_bytes.clear();
#if HID_API_VERSION >= HID_API_MAKE_VERSION(0, 14, 0)
	std::vector<uint8_t> bytes(HID_API_MAX_REPORT_DESCRIPTOR_SIZE, 0);
	const int length = hid_get_report_descriptor(p_device, bytes.data(), bytes.size());
	if (length <= 0) {
		char reason[128];
		narrow_hid_text(hid_error(p_device), "no reason given", reason, sizeof(reason));
		return Status::error(StatusCode::DEVICE_ERROR, "cannot read the HID report descriptor of '%s': %s",
				p_path.c_str(), reason);
	}
	bytes.resize(static_cast<size_t>(length));
	r_bytes = std::move(bytes);
	return Status::success();
#else
	(void)p_device;
	return Status::error(StatusCode::UNSUPPORTED, "hidapi %s cannot read the report descriptor of '%s'",
			HID_API_VERSION_STR, p_path.c_str());
#endif
}

bool hid_device_lost(int p_errno, const std::string &p_path, const char *p_hid_text) {
	bool gone_errno = p_errno == ENODEV || p_errno == EIO || p_errno == ENXIO || p_errno == EPIPE || p_errno == ENOENT;
#ifdef ESHUTDOWN // Linux's USB stack; Windows' C runtime has no such code
	gone_errno = gone_errno || p_errno == ESHUTDOWN;
#endif
	return gone_errno || !hid_node_exists(p_path) ||
			(p_hid_text != nullptr && std::strstr(p_hid_text, "isconnected") != nullptr);
}

} // namespace haptics::hid
