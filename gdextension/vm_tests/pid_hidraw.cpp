// A HID PID stick on hidraw, end to end against the real kernel: the AJ firmware's model is a
// uhid device (the kernel's hid-generic binds it and makes /dev/hidraw*; hid-pidff does not
// start on uhid in 6.1), found by list_all_devices() through hidapi and the real sysfs,
// probed, opened by the factory, and driven by the servo: a hand pressing into a floor gives
// the force the servo computed, on the wire. Then the cable is pulled and plugged back.

#include "dev_tools/uhid/pid_uhid.h"
#include "rig.h"
#include "scenarios.h"

#include <memory>

namespace haptics::vm {

namespace {

// An Arduino Leonardo's ids, as AJ-firmware sticks have.
constexpr uint16_t AJ_VENDOR = 0x2341;
constexpr uint16_t AJ_PRODUCT = 0x8036;
constexpr uint8_t SET_CONSTANT_FORCE = 0x05; // AJ's report ID.

void press_into_floor(Report &r_report, pid::ScriptedPidJoystick &p_joystick, HapticsSystem &r_system, const std::string &p_when) {
	DeviceInfo info;
	if (!r_report.check(find_listed(AJ_VENDOR, AJ_PRODUCT, BACKEND_HIDAPI, info), p_when + ": list_all_devices() finds the stick")) {
		return;
	}
	r_report.info(p_when + ": " + info.path + ", driver '" + info.driver + "', " +
			(info.openable ? "openable" : "not openable: " + info.unavailable_reason));
	r_report.check(info.driver == DRIVER_HID_PID && info.openable, p_when + ": the HID PID backend drives it");
	double max_force_n = 0.0;
	if (!open_and_run(r_report, info, r_system, max_force_n, p_when)) {
		return;
	}
	p_joystick.set_stick(0.0, 0.0);
	stand_on_floor(r_system, 0.5);
	p_joystick.set_stick(0.0, 0.8); // Pulled toward the user: the hand presses down.
	stand_on_floor(r_system, 1.0);
	const Vec3 servo = r_system.forces().total;
	r_report.wire(p_when + ": last Set Constant Force", pid_last_output(p_joystick, SET_CONSTANT_FORCE));
	r_report.check(servo.y > 0.3, p_when + ": the floor pushes the hand up");
	// AJ's direction has 256 steps (1.4 degrees): 3 % of full scale sideways.
	same_force(r_report, servo, pid_wire_n(p_joystick, max_force_n), 0.03 * max_force_n, p_when);
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
	HapticsSystem system;
	press_into_floor(report, *joystick, system, "plugged");

	stick.unplug();
	expect_unplugged(report, system, "unplugged");
	system.close_device();

	report.check(stick.plug(identity).ok(), "replugged");
	press_into_floor(report, *joystick, system, "replugged");
	system.stop();
	system.close_device();
	stick.unplug();
	return report.failed();
}

} // namespace haptics::vm
