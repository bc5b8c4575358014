#include "devices/evdev/evdev_pacing.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string_view>

namespace haptics::evdev {

namespace {

std::string read_line(const std::filesystem::path &p_path) {
	std::ifstream in(p_path);
	std::string line;
	std::getline(in, line);
	return line;
}

// "1ms", "8ms", "125us" (drivers/usb/core/endpoint.c); 0 when unreadable.
double parse_interval_s(const std::string &p_text) {
	unsigned value = 0;
	char unit = 0;
	if (std::sscanf(p_text.c_str(), "%u%c", &value, &unit) != 2 || value == 0) {
		return 0.0;
	}
	return unit == 'm' ? value * 1e-3 : (unit == 'u' ? value * 1e-6 : 0.0);
}

double interrupt_out_interval_s(const std::filesystem::path &p_interface) {
	std::error_code error;
	for (const auto &entry : std::filesystem::directory_iterator(p_interface, error)) {
		const std::string name = entry.path().filename().string();
		if (name.rfind("ep_", 0) != 0 || read_line(entry.path() / "direction") != "out" ||
				read_line(entry.path() / "type") != "Interrupt") {
			continue;
		}
		return parse_interval_s(read_line(entry.path() / "interval"));
	}
	return 0.0;
}

} // namespace

double output_report_interval_s(const std::string &p_event_path, const std::string &p_sysfs_root) {
	const std::string_view prefix = "/dev/input/";
	if (p_event_path.rfind(prefix, 0) != 0) {
		return DEFAULT_REPORT_INTERVAL_S;
	}
	std::error_code error;
	const std::filesystem::path device = std::filesystem::canonical(
			std::filesystem::path(p_sysfs_root) / "class/input" / p_event_path.substr(prefix.size()) / "device", error);
	if (error) {
		return DEFAULT_REPORT_INTERVAL_S;
	}
	// input/inputN -> the HID device -> the USB interface (it has bInterfaceNumber).
	for (std::filesystem::path dir = device; dir.has_relative_path() && dir != dir.root_path(); dir = dir.parent_path()) {
		if (std::filesystem::exists(dir / "bInterfaceNumber", error)) {
			const double interval = interrupt_out_interval_s(dir);
			return interval > 0.0 ? interval : DEFAULT_REPORT_INTERVAL_S;
		}
	}
	return DEFAULT_REPORT_INTERVAL_S;
}

double update_hold_s(const FfConstantForce &p_from, const FfConstantForce &p_to, double p_report_interval_s) {
	const int reports = (p_from.direction != p_to.direction ? 1 : 0) + (p_from.level != p_to.level ? 1 : 0);
	return reports * p_report_interval_s * PACING_MARGIN;
}

} // namespace haptics::evdev
