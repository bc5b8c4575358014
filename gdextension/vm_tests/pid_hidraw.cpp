// A HID PID stick on hidraw, end to end against the real kernel: the AJ firmware's model is a
// uhid device (the kernel's hid-generic binds it and makes /dev/hidraw*; hid-pidff does not
// start on uhid in 6.1), found by list_all_devices() through hidapi and the real sysfs,
// probed, opened by the factory, and driven by the servo: a hand pressing into a floor gives
// the force the servo computed, on the wire. Then the cable is pulled and plugged back.

#include "dev_tools/pid/scripted_pid_joystick.h"
#include "dev_tools/uhid/pid_uhid.h"
#include "engine/device_factory.h"
#include "engine/haptics_engine.h"
#include "game.h"
#include "ktest.h"
#include "scenarios.h"

#include <chrono>
#include <cmath>
#include <memory>
#include <thread>

namespace haptics::vm {

namespace {

// An Arduino Leonardo's ids, as AJ-firmware sticks have.
constexpr uint16_t AJ_VENDOR = 0x2341;
constexpr uint16_t AJ_PRODUCT = 0x8036;
constexpr uint8_t SET_CONSTANT_FORCE = 0x05; // AJ's report ID.

// The firmware's force in device space (y up is HID -Y), newtons.
Vec3 on_wire_n(const pid::ScriptedPidJoystick &p_joystick, double p_max_force_n) {
	const pid::ScriptedForce force = p_joystick.rendered_force();
	return Vec3{ force.x * p_max_force_n, -force.y * p_max_force_n, 0.0 };
}

std::vector<uint8_t> last_output(const pid::ScriptedPidJoystick &p_joystick, uint8_t p_report_id) {
	std::vector<uint8_t> last;
	for (const pid::ScriptedTransfer &transfer : p_joystick.records()) {
		if (transfer.kind == pid::TransferKind::OUTPUT && transfer.length > 0 && transfer.bytes[0] == p_report_id) {
			last = transfer.to_vector();
		}
	}
	return last;
}

// Opens the listed stick and renders a hand pressing down into a floor; true when the
// force on the wire is the servo's.
bool press_into_floor(Report &r_report, pid::ScriptedPidJoystick &p_joystick, HapticsEngine &p_engine, const char *p_when) {
	DeviceInfo info;
	if (!r_report.check(eventually([&] { return find_listed(AJ_VENDOR, AJ_PRODUCT, BACKEND_HIDAPI, info); }, 5.0), std::string(p_when) + ": list_all_devices() finds the stick")) {
		return false;
	}
	r_report.info(std::string(p_when) + ": " + info.path + ", driver '" + info.driver + "', " +
			(info.openable ? "openable" : "not openable: " + info.unavailable_reason));
	r_report.check(info.driver == DRIVER_HID_PID && info.openable, std::string(p_when) + ": the HID PID backend drives it");
	std::unique_ptr<HapticDevice> device;
	const Status opened = open_listed_device(info, {}, device);
	if (!r_report.check(opened.ok(), std::string(p_when) + ": the factory opens it " + opened.message())) {
		return false;
	}
	const double max_force_n = device->limits().max_force_n;
	const Status engine_opened = p_engine.open_device(std::move(device));
	const Status started = p_engine.start(1000.0);
	if (!r_report.check(engine_opened.ok() && started.ok(), std::string(p_when) + ": the servo runs it " + engine_opened.message() + started.message())) {
		return false;
	}
	p_joystick.set_stick(0.0, 0.0);
	stand_on_floor(p_engine, 0.5);
	p_joystick.clear_records();
	p_joystick.set_stick(0.0, 0.8); // Pulled toward the user: the hand presses down.
	stand_on_floor(p_engine, 1.0);
	const Vec3 servo = p_engine.forces().total;
	const Vec3 wire = on_wire_n(p_joystick, max_force_n);
	char text[160];
	std::snprintf(text, sizeof(text), "%s: servo (%.3f, %.3f) N, on the wire (%.3f, %.3f) N", p_when, servo.x, servo.y, wire.x,
			wire.y);
	r_report.info(text);
	r_report.wire(std::string(p_when) + ": last Set Constant Force", last_output(p_joystick, SET_CONSTANT_FORCE));
	// AJ's direction has 256 steps (1.4 degrees): 3 % of full scale sideways.
	const bool same = std::fabs(wire.x - servo.x) < 0.03 * max_force_n && std::fabs(wire.y - servo.y) < 0.03 * max_force_n;
	return r_report.check(servo.y > 0.3 && same, std::string(p_when) + ": the floor pushes the hand up, and the wire has the servo's force");
}

} // namespace

int run_pid_hidraw() {
	Report report("pid-hidraw");
	auto joystick = std::make_shared<pid::ScriptedPidJoystick>(pid::ScriptedFirmware::AJ);
	uhid::PidUhidJoystick stick(joystick);
	uhid::UhidIdentity identity;
	identity.name = "Arduino LLC Arduino Leonardo";
	identity.vendor = AJ_VENDOR;
	identity.product = AJ_PRODUCT;
	const Status plugged = stick.plug(identity);
	if (!report.check(plugged.ok(), std::string("the stick is a uhid device ") + plugged.message())) {
		return report.failed();
	}
	HapticsEngine engine;
	press_into_floor(report, *joystick, engine, "plugged");

	stick.unplug();
	const bool noticed = eventually([&] { return engine.device_status().io == DeviceIo::DISCONNECTED; }, 3.0);
	report.check(noticed, std::string("unplugged: the device says so: ") + engine.device_status().reason);
	const bool stopped = servo_stops(engine, 3.0);
	report.check(stopped, std::string("unplugged: the servo stopped: ") + engine.servo_status().message());
	engine.close_device();

	const Status replugged = stick.plug(identity);
	report.check(replugged.ok(), "replugged");
	press_into_floor(report, *joystick, engine, "replugged");
	engine.stop();
	engine.close_device();
	stick.unplug();
	return report.failed();
}

} // namespace haptics::vm
