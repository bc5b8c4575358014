// A generic force-feedback stick on evdev, end to end against the real kernel's evdev and
// ff-core: the scripted PID joystick's evdev script (the one the backend's unit tests give the
// scripted kernel) is a uinput device whose model answers ff-core's uploads and erases and
// plays what it is told. Our evdev backend finds it with list_all_devices() (sysfs and the
// devtmpfs node; there is no udev here), opens it, and the servo's force for a hand pressed
// into a floor is the FF_CONSTANT effect the device holds. The kernel's facts the scripted
// kernel models are checked against the real one (kernel_facts.cpp); the device is closed and
// reopened, destroyed in the middle of a session and made again.

#include "dev_tools/uinput/uinput_ff_device.h"
#include "devices/evdev/evdev_backend.h"
#include "rig.h"
#include "scenarios.h"
#include "system/device_factory.h"
#include "system/haptics_system.h"

#include <cmath>
#include <cstdio>
#include <memory>

namespace haptics::vm {

namespace {

constexpr const char *PHYS = "haptics-uinput/ffb";

// The force the device plays, in device space (y up = axis -y), newtons.
Vec3 played_n(const uinput::UinputFfDevice &p_stick, double p_max_force_n) {
	const evdev::ScriptedRenderedForce force = p_stick.rendered();
	return Vec3{ force.axis_x * p_max_force_n, -force.axis_y * p_max_force_n, 0.0 };
}

// The last record of p_kind, or false.
bool last_record(const uinput::UinputFfDevice &p_stick, uinput::UinputRecord::Kind p_kind, uinput::UinputRecord &r_record) {
	bool found = false;
	for (const uinput::UinputRecord &record : p_stick.records()) {
		if (record.kind == p_kind) {
			r_record = record;
			found = true;
		}
	}
	return found;
}

// Finds the stick in the list; with p_reopen, opens it, closes it and opens it again first
// (what the game does when it reconnects), checking the second open uploaded a new effect.
std::unique_ptr<HapticDevice> open_listed(Report &r_report, uinput::UinputFfDevice &p_stick, const char *p_when, bool p_reopen) {
	const evdev::ScriptedEvdevScript script = evdev::scripted_joystick_script();
	DeviceInfo info;
	if (!r_report.check(find_listed(script.vendor, script.product, BACKEND_EVDEV, info, 5.0),
				std::string(p_when) + ": list_all_devices() finds the stick's event node")) {
		return nullptr;
	}
	r_report.info(std::string(p_when) + ": " + info.id + " at " + info.path + ", driver '" + info.driver + "', " +
			(info.openable ? "openable" : "not openable: " + info.unavailable_reason));
	r_report.check(info.id == std::string("evdev:") + PHYS && info.path == p_stick.event_path() && info.driver == DRIVER_EVDEV &&
					info.openable,
			std::string(p_when) + ": listed by its phys, at the node uinput made, openable by the evdev backend");
	std::unique_ptr<HapticDevice> device;
	if (!p_reopen) {
		const Status opened = open_listed_device(info, {}, device);
		r_report.check(opened.ok(), std::string(p_when) + ": the factory opens it " + opened.message());
		return opened.ok() ? std::move(device) : nullptr;
	}
	auto evdev_device = std::make_unique<evdev::EvdevDevice>(evdev::linux_evdev_syscalls(), evdev::device_config_for(info));
	Status opened = evdev_device->open();
	evdev_device->close(); // The kernel erases what the closed file held (we erase it first).
	p_stick.clear_records();
	if (opened) {
		opened = evdev_device->open();
	}
	uinput::UinputRecord upload;
	const bool fresh = last_record(p_stick, uinput::UinputRecord::Kind::UPLOAD, upload) && !upload.replaced;
	r_report.check(opened.ok() && fresh && p_stick.effects_in_use() == 1,
			std::string(p_when) + ": opened, closed and opened again: a new effect uploaded (id " + std::to_string(upload.id) +
					"), not an update of the erased one " + opened.message());
	device = std::move(evdev_device);
	return opened.ok() ? std::move(device) : nullptr;
}

// Runs the servo on the listed stick with the hand pressed into a floor; true when the
// constant force the device holds is the servo's.
bool press_into_floor(Report &r_report, uinput::UinputFfDevice &p_stick, HapticsSystem &p_system, const char *p_when,
		bool p_reopen = false) {
	std::unique_ptr<HapticDevice> device = open_listed(r_report, p_stick, p_when, p_reopen);
	if (!device) {
		return false;
	}
	const double max_force_n = device->limits().max_force_n;
	const Status engine_opened = p_system.open_device(std::move(device));
	const Status started = p_system.start(1000.0);
	if (!r_report.check(engine_opened.ok() && started.ok(),
				std::string(p_when) + ": the servo runs it " + engine_opened.message() + started.message())) {
		return false;
	}
	(void)p_stick.set_stick_axes(0.0, 0.0);
	stand_on_floor(p_system, 0.4);
	(void)p_stick.set_stick_axes(0.0, 0.8); // Pulled toward the user: the hand presses down.
	stand_on_floor(p_system, 1.0);
	const Vec3 servo = p_system.forces().total;
	const Vec3 played = played_n(p_stick, max_force_n);
	uinput::UinputRecord upload;
	const bool uploaded = p_stick.last_upload(evdev::EVDEV_FF_CONSTANT, upload);
	char text[200];
	std::snprintf(text, sizeof(text), "%s: servo (%.3f, %.3f) N; last FF_CONSTANT id %d direction 0x%04x level %d -> (%.3f, %.3f) N",
			p_when, servo.x, servo.y, upload.id, upload.effect.direction, upload.effect.constant_level, played.x, played.y);
	r_report.info(text);
	r_report.wire(std::string(p_when) + ": last FF_CONSTANT ff_effect the device got", upload.bytes);
	// Level steps are 1/32767 of full scale and direction steps 1/65536 of a turn.
	const bool same = std::fabs(played.x - servo.x) < 0.002 * max_force_n && std::fabs(played.y - servo.y) < 0.002 * max_force_n;
	return r_report.check(uploaded && servo.y > 0.3 && p_stick.rendered().playing == 1 && same,
			std::string(p_when) + ": the floor pushes the hand up, and the device plays the servo's force");
}

} // namespace

int run_evdev_uinput() {
	Report report("evdev-uinput");
	uinput::UinputFfDevice stick(evdev::scripted_joystick_script());
	const Status created = stick.create(PHYS);
	if (!report.check(created.ok(), "the stick is a uinput device at " + stick.event_path() + " " + created.message())) {
		return report.failed();
	}
	check_kernel_facts(report, stick);

	HapticsSystem system;
	press_into_floor(report, stick, system, "created");
	system.stop();
	system.close_device();
	uinput::UinputRecord erased;
	const bool erased_ours = last_record(stick, uinput::UinputRecord::Kind::ERASE, erased) && stick.effects_in_use() == 0;
	report.check(erased_ours, "closed: our backend erased its effect (id " + std::to_string(erased.id) + ")");
	press_into_floor(report, stick, system, "reopened", true);

	stick.destroy(); // In the middle of the session.
	const bool noticed = eventually([&] { return system.device_status().io == DeviceIo::DISCONNECTED; }, 3.0);
	report.check(noticed && system.device_status().reason[0] != '\0',
			std::string("destroyed: the device says DISCONNECTED: ") + system.device_status().reason.c_str());
	const bool stopped = servo_stops(system, 3.0);
	report.check(stopped, std::string("destroyed: the servo stopped: ") + system.servo_status().message());
	system.close_device();

	const Status made = stick.create(PHYS);
	report.check(made.ok(), "made again at " + stick.event_path() + " " + made.message());
	press_into_floor(report, stick, system, "made again");
	system.stop();
	system.close_device();
	stick.destroy();
	return report.failed();
}

} // namespace haptics::vm
