#include "devices/hid/hidraw_sysfs.h"

#include "devices/hid/hidapi_open.h"

#include <hidapi.h>

// hidapi's Windows backend: its paths are device interface names, not /dev/hidrawN, and
// Windows has no sysfs. Each answer is what Windows offers (hidraw_sysfs.h).

namespace haptics::hid {

int32_t hidraw_index(std::string_view) {
	return -1;
}

std::string hidraw_hid_device_sysfs_dir(const std::string &, const std::string &) {
	return {};
}

// Windows lets a normal user open a HID device for the descriptor (no udev rules to miss), so
// the probe opens it briefly. The rebuilt descriptor carries the same reports, fields and
// usages as the device's own, which is all the PID layout parser reads.
Status read_hidraw_report_descriptor(const std::string &p_hidraw_path, std::vector<uint8_t> &r_bytes,
		const std::string &) {
	r_bytes.clear();
	hid_device *device = nullptr;
	const Status opened = open_hidraw_device(p_hidraw_path, "HID descriptor", device);
	if (!opened) {
		return Status::error(opened.code(), "cannot read the HID report descriptor of '%s': %s", p_hidraw_path.c_str(),
				opened.message());
	}
	const Status read = read_open_report_descriptor(device, p_hidraw_path, r_bytes);
	hid_close(device);
	return read;
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

// Windows gives an application no reset of a USB device its HID driver owns.
Status reset_usb_device_of(const std::string &, const std::string &) {
	return Status::error(StatusCode::UNSUPPORTED, "Windows offers no USB reset of a HID device to a program");
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
