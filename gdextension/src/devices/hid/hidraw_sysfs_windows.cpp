#include "devices/hid/hidraw_sysfs.h"

// hidapi's Windows backend: its paths are device interface names, not /dev/hidrawN, and
// Windows has no sysfs. Each answer is what Windows offers (hidraw_sysfs.h).

namespace haptics::hid {

int32_t hidraw_index(std::string_view) {
	return -1;
}

std::string hidraw_hid_device_sysfs_dir(const std::string &, const std::string &) {
	return {};
}

Status read_hidraw_report_descriptor(const std::string &p_hidraw_path, std::vector<uint8_t> &r_bytes,
		const std::string &) {
	r_bytes.clear();
	return Status::error(StatusCode::UNSUPPORTED,
			"cannot read the HID report descriptor of '%s' on Windows (hidapi 0.13 has no call for it; "
			"0.14 rebuilds it from Windows' parsed form)",
			p_hidraw_path.c_str());
}

// The Linux check guards against a hidapi bug of its hidraw backend; the Windows backend
// validates its own paths (CreateFile on the interface name).
bool is_hidraw_node(const std::string &, std::string *, const std::string &) {
	return true;
}

// Windows' HID stack has no kernel force-feedback driver bound to a HID PID device: the
// game talks to it directly (DirectInput's own PID driver is a user-mode client like us).
bool kernel_ff_bound(const std::string &, const std::string &) {
	return false;
}

// A removed device's interface name cannot be checked without opening it: hidapi's open and
// its reads say so.
bool hid_node_exists(const std::string &) {
	return true;
}

int hid_node_access_errno(const std::string &) {
	return 0;
}

} // namespace haptics::hid
