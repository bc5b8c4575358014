#include "rig.h"

#include "system/device_factory.h"

#include <sys/klog.h>
#include <sys/utsname.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <thread>

namespace haptics::vm {

std::vector<DeviceInfo> listed(uint16_t p_vendor, uint16_t p_product, std::string_view p_backend) {
	std::vector<DeviceInfo> found;
	for (const DeviceInfo &info : list_all_devices().devices) {
		if (info.vendor_id == p_vendor && info.product_id == p_product && (p_backend.empty() || info.backend == p_backend)) {
			found.push_back(info);
		}
	}
	return found;
}

bool find_listed(uint16_t p_vendor, uint16_t p_product, std::string_view p_backend, DeviceInfo &r_info, double p_seconds) {
	return eventually(
			[&] {
				const std::vector<DeviceInfo> found = listed(p_vendor, p_product, p_backend);
				if (!found.empty()) {
					r_info = found.front();
				}
				return !found.empty();
			},
			p_seconds);
}

void stand_on_floor(HapticsSystem &p_system, double p_seconds) {
	Frame frame;
	add_contact(frame, Vec3{ 0.0, 1.0, 0.0 });
	const int count = static_cast<int>(p_seconds * 50.0);
	for (int i = 0; i < count; ++i) {
		frame.sequence = static_cast<uint64_t>(i);
		(void)p_system.submit_frame(frame);
		std::this_thread::sleep_for(std::chrono::milliseconds(20));
	}
}

bool open_and_run(Report &r_report, const DeviceInfo &p_info, HapticsSystem &r_system, double &r_max_force_n,
		const std::string &p_when) {
	std::unique_ptr<HapticDevice> device;
	const Status opened = open_listed_device(p_info, {}, device);
	if (!r_report.check(opened.ok(), p_when + ": the factory opens " + p_info.path + " " + opened.message())) {
		return false;
	}
	r_max_force_n = device->limits().max_force_n;
	const Status engine_opened = r_system.open_device(std::move(device));
	const Status started = engine_opened ? r_system.start(1000.0) : engine_opened;
	return r_report.check(started.ok(), p_when + ": the servo runs it at 1 kHz " + started.message());
}

bool same_force(Report &r_report, const Vec3 &p_servo, const Vec3 &p_wire, double p_tolerance_n, const std::string &p_what) {
	char text[200];
	std::snprintf(text, sizeof(text), "%s: servo (%.3f, %.3f) N, on the wire (%.3f, %.3f) N", p_what.c_str(), p_servo.x,
			p_servo.y, p_wire.x, p_wire.y);
	const bool same = std::fabs(p_wire.x - p_servo.x) < p_tolerance_n && std::fabs(p_wire.y - p_servo.y) < p_tolerance_n;
	return r_report.check(same, text);
}

bool servo_stops(const HapticsSystem &p_system, double p_seconds) {
	return eventually([&] { return !p_system.servo_status().ok(); }, p_seconds);
}

void expect_unplugged(Report &r_report, HapticsSystem &r_system, const std::string &p_when) {
	const bool noticed = eventually([&] { return r_system.device_status().io == DeviceIo::DISCONNECTED; }, 5.0);
	r_report.check(noticed, p_when + ": the device says so: " + r_system.device_status().reason.c_str());
	const bool stopped = servo_stops(r_system, 3.0);
	r_report.check(stopped, p_when + ": the servo stopped: " + r_system.servo_status().message());
}

Vec3 pid_wire_n(const pid::ScriptedPidJoystick &p_joystick, double p_max_force_n) {
	const pid::ScriptedForce force = p_joystick.rendered_force();
	return Vec3{ force.x * p_max_force_n, -force.y * p_max_force_n, 0.0 };
}

std::vector<uint8_t> pid_last_output(const pid::ScriptedPidJoystick &p_joystick, uint8_t p_report_id) {
	std::vector<uint8_t> last;
	for (const pid::ScriptedTransfer &transfer : p_joystick.records()) {
		if (transfer.kind == pid::TransferKind::OUTPUT && transfer.length > 0 && transfer.bytes[0] == p_report_id) {
			last = transfer.to_vector();
		}
	}
	return last;
}

size_t pid_output_count(const pid::ScriptedPidJoystick &p_joystick, uint8_t p_report_id) {
	size_t count = 0;
	for (const pid::ScriptedTransfer &transfer : p_joystick.records()) {
		count += transfer.kind == pid::TransferKind::OUTPUT && transfer.length > 0 && transfer.bytes[0] == p_report_id;
	}
	return count;
}

int kernel_log_count(std::string_view p_text) {
	const int size = ::klogctl(10 /* SYSLOG_ACTION_SIZE_BUFFER */, nullptr, 0);
	if (size <= 0) {
		return -1;
	}
	std::string log(static_cast<size_t>(size), '\0');
	const int got = ::klogctl(3 /* SYSLOG_ACTION_READ_ALL */, log.data(), size);
	if (got < 0) {
		return -1;
	}
	log.resize(static_cast<size_t>(got));
	int count = 0;
	for (size_t at = log.find(p_text); at != std::string::npos; at = log.find(p_text, at + 1)) {
		++count;
	}
	return count;
}

std::string kernel_release() {
	utsname name{};
	return ::uname(&name) == 0 ? name.release : "";
}

bool kernel_older_than(int p_major, int p_minor) {
	int major = 0;
	int minor = 0;
	if (std::sscanf(kernel_release().c_str(), "%d.%d", &major, &minor) != 2) {
		return false;
	}
	return major < p_major || (major == p_major && minor < p_minor);
}

} // namespace haptics::vm
