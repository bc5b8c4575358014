#include "devices/evdev/evdev_enumeration.h"

#include "devices/evdev/evdev_abi.h"
#include "devices/evdev/evdev_backend.h"
#include "devices/evdev/evdev_bits.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace haptics::evdev {

namespace fs = std::filesystem;

namespace {

// The first line of a sysfs attribute, or "" when it cannot be read.
std::string read_attribute(const fs::path &p_path) {
	std::ifstream file(p_path);
	std::string line;
	if (!file || !std::getline(file, line)) {
		return {};
	}
	while (!line.empty() && (line.back() == '\n' || line.back() == '\r' || line.back() == ' ')) {
		line.pop_back();
	}
	return line;
}

uint16_t hex_u16(const std::string &p_text) {
	char *end = nullptr;
	const unsigned long value = std::strtoul(p_text.c_str(), &end, 16);
	return end != p_text.c_str() && value <= 0xffff ? static_cast<uint16_t>(value) : 0;
}

// "event12" -> 12; -1 for anything else.
long event_number(const std::string &p_name) {
	if (p_name.size() <= 5 || p_name.compare(0, 5, "event") != 0) {
		return -1;
	}
	long number = 0;
	for (size_t i = 5; i < p_name.size(); ++i) {
		if (p_name[i] < '0' || p_name[i] > '9' || number > 1000000) {
			return -1;
		}
		number = number * 10 + (p_name[i] - '0');
	}
	return number;
}

bool is_hex_run(const std::string &p_text, size_t p_begin, size_t p_count) {
	for (size_t i = p_begin; i < p_begin + p_count; ++i) {
		if (!std::isxdigit(static_cast<unsigned char>(p_text[i]))) {
			return false;
		}
	}
	return true;
}

// hid-core names its devices "%04X:%04X:%04X.%04X" (bus, vendor, product, instance).
bool has_hid_device_name(const std::string &p_name) {
	return p_name.size() == 19 && p_name[4] == ':' && p_name[9] == ':' && p_name[14] == '.' && is_hex_run(p_name, 0, 4) &&
			is_hex_run(p_name, 5, 4) && is_hex_run(p_name, 10, 4) && is_hex_run(p_name, 15, 4);
}

bool is_hid_device_dir(const fs::path &p_dir) {
	std::error_code error;
	const fs::path subsystem = fs::read_symlink(p_dir / "subsystem", error);
	if (!error && subsystem.filename() == "hid") {
		return true;
	}
	return has_hid_device_name(p_dir.filename().string());
}

// udev's /dev/input/by-path link to p_event (e.g. "pci-0000:00:14.0-usb-0:2:1.0-event-joystick"):
// as stable as phys, for the nodes whose driver set no phys. "" when there is none.
std::string by_path_name(const std::string &p_dev_root, const std::string &p_event) {
	std::error_code error;
	fs::directory_iterator links(fs::path(p_dev_root) / "by-path", error);
	if (error) {
		return {};
	}
	std::string best;
	for (const fs::directory_entry &link : links) {
		const fs::path target = fs::read_symlink(link.path(), error);
		const std::string name = link.path().filename().string();
		// Sorted choice: the directory order is arbitrary, the id must not be.
		if (!error && target.filename() == p_event && (best.empty() || name < best)) {
			best = name;
		}
	}
	return best;
}

} // namespace

std::string evdev_hid_device_sysfs_dir(const std::string &p_sysfs_root, const std::string &p_event_name) {
	std::error_code error;
	fs::path dir = fs::canonical(fs::path(p_sysfs_root) / p_event_name / "device", error);
	if (error) {
		return {};
	}
	// input device -> "input" -> the HID device: a few levels; the bound keeps a strange
	// tree from walking to /.
	for (int level = 0; level < 8 && dir.has_relative_path(); ++level, dir = dir.parent_path()) {
		if (is_hid_device_dir(dir)) {
			return dir.string();
		}
	}
	return {};
}

void enumerate_evdev_devices(std::vector<DeviceInfo> &r_devices, std::vector<std::string> &r_warnings,
		const std::string &p_sysfs_root, const std::string &p_dev_root) {
	std::error_code error;
	fs::directory_iterator entries(p_sysfs_root, error);
	if (error) {
		r_warnings.push_back("evdev: cannot list " + p_sysfs_root + " (" + error.message() +
				"): no input devices are visible here");
		return;
	}
	std::vector<std::pair<long, std::string>> events;
	for (const fs::directory_entry &entry : entries) {
		const std::string name = entry.path().filename().string();
		const long number = event_number(name);
		if (number >= 0) {
			events.emplace_back(number, name);
		}
	}
	std::sort(events.begin(), events.end());

	const std::shared_ptr<EvdevSyscalls> sys = linux_evdev_syscalls();
	for (const auto &[number, event] : events) {
		const fs::path device = fs::path(p_sysfs_root) / event / "device";
		const std::string ff_text = read_attribute(device / "capabilities" / "ff");
		uint8_t ff_bits[EVDEV_FF_BITS_BYTES] = {};
		const std::string what = "evdev: " + event + " capabilities/ff";
		const Status parsed = parse_sysfs_bitmask(ff_text, KERNEL_LONG_BITS, what.c_str(), ff_bits, sizeof(ff_bits));
		if (!parsed) {
			r_warnings.emplace_back(parsed.message());
			continue;
		}
		if (!test_bit(ff_bits, sizeof(ff_bits), EVDEV_FF_CONSTANT) && !test_bit(ff_bits, sizeof(ff_bits), EVDEV_FF_RUMBLE)) {
			continue; // No force feedback (ff-core shows FF_RUMBLE for FF_PERIODIC too).
		}
		DeviceInfo info;
		std::string stable = read_attribute(device / "phys");
		if (stable.empty()) {
			stable = by_path_name(p_dev_root, event);
		}
		info.id = "evdev:" + (stable.empty() ? event : stable);
		info.backend = BACKEND_EVDEV;
		info.driver = DRIVER_EVDEV;
		info.path = p_dev_root + "/" + event;
		info.vendor_id = hex_u16(read_attribute(device / "id" / "vendor"));
		info.product_id = hex_u16(read_attribute(device / "id" / "product"));
		info.product = read_attribute(device / "name");
		info.serial = read_attribute(device / "uniq");
		info.known_haptic = true;
		const DeviceAvailability availability = probe(info, *sys);
		info.openable = availability.openable;
		info.unavailable_reason = availability.reason;
		r_devices.push_back(std::move(info));
	}
}

} // namespace haptics::evdev
