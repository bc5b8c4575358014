#include "devices/hid/hidraw_sysfs.h"

#include "devices/hid/report_descriptor.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <linux/usbdevice_fs.h>
#include <memory>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

namespace haptics::hid {

namespace {

constexpr std::string_view HIDRAW_PREFIX = "/dev/hidraw";

std::string class_device_dir(const std::string &p_hidraw_path, const std::string &p_sysfs_root) {
	const int32_t index = hidraw_index(p_hidraw_path);
	if (index < 0) {
		return {};
	}
	return p_sysfs_root + "/class/hidraw/hidraw" + std::to_string(index) + "/device";
}

// True when the ff capability bitmap (hex words separated by spaces) has any bit set.
bool capability_nonzero(const std::string &p_text) {
	for (const char c : p_text) {
		if ((c >= '1' && c <= '9') || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F')) {
			return true;
		}
	}
	return false;
}

} // namespace

int32_t hidraw_index(std::string_view p_path) {
	if (p_path.substr(0, HIDRAW_PREFIX.size()) != HIDRAW_PREFIX || p_path.size() == HIDRAW_PREFIX.size() ||
			p_path.size() > HIDRAW_PREFIX.size() + 6) {
		return -1;
	}
	int32_t index = 0;
	for (const char c : p_path.substr(HIDRAW_PREFIX.size())) {
		if (c < '0' || c > '9') {
			return -1;
		}
		index = index * 10 + (c - '0');
	}
	return index;
}

std::string hidraw_hid_device_sysfs_dir(const std::string &p_hidraw_path, const std::string &p_sysfs_root) {
	const std::string link = class_device_dir(p_hidraw_path, p_sysfs_root);
	if (link.empty()) {
		return {};
	}
	const std::unique_ptr<char, decltype(&std::free)> resolved(realpath(link.c_str(), nullptr), &std::free);
	return resolved ? std::string(resolved.get()) : std::string();
}

Status read_hidraw_report_descriptor(const std::string &p_hidraw_path, std::vector<uint8_t> &r_bytes,
		const std::string &p_sysfs_root) {
	r_bytes.clear();
	const std::string dir = class_device_dir(p_hidraw_path, p_sysfs_root);
	if (dir.empty()) {
		return Status::error(StatusCode::INVALID_ARGUMENT, "'%s' is not a /dev/hidrawN path", p_hidraw_path.c_str());
	}
	const std::string file = dir + "/report_descriptor";
	std::ifstream in(file, std::ios::binary);
	if (!in) {
		return Status::error(StatusCode::NO_DEVICE, "cannot read %s: %s", file.c_str(), std::strerror(errno));
	}
	r_bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
	if (r_bytes.empty() || r_bytes.size() > MAX_DESCRIPTOR_BYTES) {
		const size_t size = r_bytes.size();
		r_bytes.clear();
		return Status::error(StatusCode::DEVICE_ERROR, "%s holds %zu bytes (expected 1..%zu)", file.c_str(), size,
				MAX_DESCRIPTOR_BYTES);
	}
	return Status::success();
}

bool is_hidraw_node(const std::string &p_path, std::string *r_reason, const std::string &p_sysfs_root) {
	struct stat info;
	if (stat(p_path.c_str(), &info) != 0) {
		if (r_reason) {
			*r_reason = p_path + ": " + std::strerror(errno);
		}
		return false;
	}
	if (S_ISCHR(info.st_mode)) {
		const std::string link = p_sysfs_root + "/dev/char/" + std::to_string(major(info.st_rdev)) + ":" +
				std::to_string(minor(info.st_rdev)) + "/subsystem";
		const std::unique_ptr<char, decltype(&std::free)> resolved(realpath(link.c_str(), nullptr), &std::free);
		if (resolved && std::filesystem::path(resolved.get()).filename() == "hidraw") {
			return true;
		}
	}
	if (r_reason) {
		*r_reason = p_path + " is not a hidraw device";
	}
	return false;
}

bool kernel_ff_bound(const std::string &p_hidraw_path, const std::string &p_sysfs_root) {
	const std::string dir = class_device_dir(p_hidraw_path, p_sysfs_root);
	if (dir.empty()) {
		return false;
	}
	std::error_code error;
	std::filesystem::directory_iterator it(dir + "/input", error);
	if (error) {
		return false;
	}
	for (const std::filesystem::directory_entry &entry : it) {
		if (entry.path().filename().string().rfind("input", 0) != 0) {
			continue;
		}
		std::ifstream in(entry.path() / "capabilities" / "ff");
		std::string text;
		if (in && std::getline(in, text) && capability_nonzero(text)) {
			return true;
		}
	}
	return false;
}

Status reset_usb_device_of(const std::string &p_hidraw_path, const std::string &p_sysfs_root) {
	std::filesystem::path dir = hidraw_hid_device_sysfs_dir(p_hidraw_path, p_sysfs_root);
	// The HID device sits under its USB interface, under the USB device with busnum/devnum.
	for (; !dir.empty() && dir != dir.root_path(); dir = dir.parent_path()) {
		std::ifstream bus_file(dir / "busnum");
		std::ifstream dev_file(dir / "devnum");
		int bus = 0;
		int dev = 0;
		if (!(bus_file >> bus) || !(dev_file >> dev)) {
			continue;
		}
		char node[40];
		std::snprintf(node, sizeof(node), "/dev/bus/usb/%03d/%03d", bus, dev);
		const int fd = ::open(node, O_WRONLY | O_CLOEXEC);
		if (fd < 0) {
			return Status::error(StatusCode::DEVICE_ERROR, "cannot reset %s: %s", node, std::strerror(errno));
		}
		const int reset = ::ioctl(fd, USBDEVFS_RESET, 0);
		const int reset_errno = errno;
		::close(fd);
		if (reset != 0) {
			return Status::error(StatusCode::DEVICE_ERROR, "USB reset of %s failed: %s", node, std::strerror(reset_errno));
		}
		return Status::success();
	}
	return Status::error(StatusCode::NO_DEVICE, "%s is not a USB device", p_hidraw_path.c_str());
}

bool hid_node_exists(const std::string &p_path) {
	return ::access(p_path.c_str(), F_OK) == 0;
}

int hid_node_access_errno(const std::string &p_path) {
	return ::access(p_path.c_str(), R_OK | W_OK) == 0 ? 0 : errno;
}

} // namespace haptics::hid
