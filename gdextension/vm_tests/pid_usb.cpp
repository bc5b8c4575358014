// A HID PID stick on USB, end to end against the real kernel: the firmware model is a USB
// gadget on dummy_hcd, so usbhid binds it as it binds a real stick and hid-pidff tries to
// drive it. The probe must choose as the kernel did: when hid-pidff refused the descriptor
// (AJ's on Linux 6.1: no Start Delay), our PID backend drives hidraw; when hid-pidff took it
// (AJ with a Start Delay), hidraw is the kernel's and our evdev backend drives the event node,
// so the bytes on the wire are the kernel's hid-pidff's. Each renders the servo's force, is
// unplugged (the gadget unbound) and plugged back, then stops taking output for a while and
// for good (pid_outage.cpp). On the kernel's path a burst of changing
// forces must still leave the last one on the wire: hid-pidff drops updates that outrun the
// interrupt endpoint without telling anyone.

#include "dev_tools/gadget/hid_gadget.h"
#include "dev_tools/uhid/pid_uhid.h"
#include "devices/evdev/evdev_ff.h"
#include "rig.h"
#include "scenarios.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <thread>

namespace haptics::vm {

namespace {

constexpr uint16_t AJ_VENDOR = 0x2341;
constexpr uint16_t AJ_PRODUCT = 0x8036;
constexpr uint8_t SET_EFFECT = 0x01;
constexpr uint8_t SET_CONSTANT_FORCE = 0x05;
// usbhid probes, hid-pidff initialises (Pool, Block Load) after hidraw appears: time for
// both under emulation.
constexpr double SETTLE_S = 1.5;

std::string describe(const DeviceInfo &p_info) {
	return p_info.backend + " " + p_info.path + ", driver '" + p_info.driver + "', " +
			(p_info.openable ? "openable" : "not openable: " + p_info.unavailable_reason);
}

// The entry the game would open, after checking the probe chose as the kernel did.
bool choose(Report &r_report, bool p_kernel_owns, DeviceInfo &r_choice, const std::string &p_when) {
	DeviceInfo hid;
	if (!r_report.check(find_listed(AJ_VENDOR, AJ_PRODUCT, BACKEND_HIDAPI, hid), p_when + ": list_all_devices() finds the hidraw node")) {
		return false;
	}
	std::this_thread::sleep_for(std::chrono::duration<double>(SETTLE_S));
	const std::vector<DeviceInfo> hids = listed(AJ_VENDOR, AJ_PRODUCT, BACKEND_HIDAPI);
	const std::vector<DeviceInfo> events = listed(AJ_VENDOR, AJ_PRODUCT, BACKEND_EVDEV);
	int openable = 0;
	for (const std::vector<DeviceInfo> *list : { &hids, &events }) {
		for (const DeviceInfo &info : *list) {
			r_report.info(p_when + ": " + describe(info));
			if (info.openable) {
				r_choice = info;
				++openable;
			}
		}
	}
	if (!r_report.check(openable == 1, p_when + ": exactly one path is openable")) {
		return false;
	}
	const std::string_view expected = p_kernel_owns ? BACKEND_EVDEV : BACKEND_HIDAPI;
	return r_report.check(r_choice.backend == expected, p_when + ": the probe chose " + r_choice.backend + " (" + (p_kernel_owns ? "hid-pidff drives it" : "hid-pidff refused it") + ")");
}

bool press_into_floor(Report &r_report, pid::ScriptedPidJoystick &p_joystick, HapticsSystem &r_system,
		const DeviceInfo &p_info, double &r_max_force_n, const std::string &p_when) {
	if (!open_and_run(r_report, p_info, r_system, r_max_force_n, p_when)) {
		return false;
	}
	p_joystick.set_stick(0.0, 0.0);
	stand_on_floor(r_system, 0.5);
	p_joystick.set_stick(0.0, 0.8);
	stand_on_floor(r_system, 1.0);
	const Vec3 servo = r_system.forces().total;
	r_report.wire(p_when + ": last Set Effect", pid_last_output(p_joystick, SET_EFFECT));
	r_report.wire(p_when + ": last Set Constant Force", pid_last_output(p_joystick, SET_CONSTANT_FORCE));
	r_report.check(servo.y > 0.3, p_when + ": the floor pushes the hand up");
	return same_force(r_report, servo, pid_wire_n(p_joystick, r_max_force_n), 0.03 * r_max_force_n, p_when);
}

// On the kernel's path: the force held past one effect's length is still what the firmware
// renders, and the Duration it was given is finite. hid-pidff before 6.15 passes ff.rst's
// "infinite" length 0 on as Duration 0, which AJ's firmware ends at once (issue 38, item 4).
void held_past_one_length(Report &r_report, pid::ScriptedPidJoystick &p_joystick, HapticsSystem &r_system,
		double p_max_force_n, const std::string &p_when) {
	stand_on_floor(r_system, 2.0 * evdev::CONSTANT_EFFECT_LENGTH_MS / 1000.0);
	uint16_t duration = 0;
	bool infinite = false;
	for (uint8_t block = 1; block <= pid::ScriptedPidJoystick::MAX_EFFECTS; ++block) {
		const pid::ScriptedEffect effect = p_joystick.effect(block);
		if (effect.allocated && effect.playing) {
			duration = effect.duration;
			infinite = effect.duration_infinite;
		}
	}
	r_report.info(p_when + ": the playing effect's Duration is " + std::to_string(duration) + (infinite ? " (infinite)" : " ms"));
	r_report.check(duration != 0 || infinite, p_when + ": the Duration the firmware got is not 0");
	const pid::ScriptedForce held = p_joystick.rendered_force();
	const Vec3 servo = r_system.forces().total;
	char text[160];
	std::snprintf(text, sizeof(text), "%s: after %.1f s the firmware renders (%.3f, %.3f) of full force, the servo (%.3f, %.3f) N",
			p_when.c_str(), 2.0 * evdev::CONSTANT_EFFECT_LENGTH_MS / 1000.0, held.x, held.y, servo.x, servo.y);
	r_report.info(text);
	r_report.check(held.playing_effects > 0 && std::hypot(held.x, held.y) * p_max_force_n > 0.5 * length(servo),
			p_when + ": the held force is still rendered past one effect's length");
}

// The stick swept in a circle for p_seconds, the servo's force changing every tick, then
// held: the force on the wire must be the servo's last.
void burst(Report &r_report, pid::ScriptedPidJoystick &p_joystick, HapticsSystem &r_system, double p_max_force_n,
		const std::string &p_when) {
	const int queue_full_before = kernel_log_count("output queue full");
	const size_t constants_before = pid_output_count(p_joystick, SET_CONSTANT_FORCE);
	const size_t effects_before = pid_output_count(p_joystick, SET_EFFECT);
	const auto start = std::chrono::steady_clock::now();
	std::thread frames([&] { stand_on_floor(r_system, 2.0); });
	for (double t = 0.0; t < 1.0;) {
		const double angle = 2.0 * std::numbers::pi * 4.0 * t;
		p_joystick.set_stick(0.4 * std::sin(angle), 0.5 + 0.3 * std::cos(angle));
		std::this_thread::sleep_for(std::chrono::milliseconds(1));
		t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
	}
	p_joystick.set_stick(0.25, 0.7);
	frames.join();
	const int dropped = kernel_log_count("output queue full") - queue_full_before;
	char text[200];
	std::snprintf(text, sizeof(text), "%s: %zu Set Effect and %zu Set Constant Force reports reached the device; the kernel dropped %d (\"output queue full\")",
			p_when.c_str(), pid_output_count(p_joystick, SET_EFFECT) - effects_before,
			pid_output_count(p_joystick, SET_CONSTANT_FORCE) - constants_before, dropped);
	r_report.info(text);
	r_report.wire(p_when + ": last Set Effect", pid_last_output(p_joystick, SET_EFFECT));
	r_report.wire(p_when + ": last Set Constant Force", pid_last_output(p_joystick, SET_CONSTANT_FORCE));
	r_report.check(dropped == 0, p_when + ": no update was dropped");
	same_force(r_report, r_system.forces().total, pid_wire_n(p_joystick, p_max_force_n), 0.03 * p_max_force_n,
			p_when + ": the wire holds the last command");
}

void run_stick(Report &r_report, pid::ScriptedFirmware p_firmware, bool p_kernel_owns, const std::string &p_label) {
	auto joystick = std::make_shared<pid::ScriptedPidJoystick>(p_firmware);
	uhid::PidHidModel model(joystick);
	gadget::HidGadget stick(model, model);
	gadget::GadgetIdentity identity;
	identity.vendor = AJ_VENDOR;
	identity.product = AJ_PRODUCT;
	identity.manufacturer = "Arduino LLC";
	identity.product_name = "Arduino Leonardo";
	const Status created = stick.create(identity, joystick->descriptor());
	const Status plugged = created ? stick.plug() : created;
	if (!r_report.check(plugged.ok(), p_label + ": the stick is a USB gadget " + plugged.message())) {
		return;
	}
	HapticsSystem system;
	DeviceInfo info;
	double max_force_n = 0.0;
	if (choose(r_report, p_kernel_owns, info, p_label) &&
			press_into_floor(r_report, *joystick, system, info, max_force_n, p_label) && p_kernel_owns) {
		held_past_one_length(r_report, *joystick, system, max_force_n, p_label + ", held");
		burst(r_report, *joystick, system, max_force_n, p_label + ", burst");
	}
	(void)stick.unplug();
	expect_unplugged(r_report, system, p_label + ", unplugged");
	system.close_device();
	joystick->set_plugged(false); // The firmware restarts when power returns.
	joystick->set_plugged(true);
	const Status replugged = stick.plug();
	if (r_report.check(replugged.ok(), p_label + ": replugged " + replugged.message()) &&
			choose(r_report, p_kernel_owns, info, p_label + ", replugged") &&
			press_into_floor(r_report, *joystick, system, info, max_force_n, p_label + ", replugged")) {
		// Last: a STALL lasts until the host clears it, which nothing here does.
		check_outages(r_report, stick, *joystick, system, info, max_force_n, p_kernel_owns, p_label);
	}
	const gadget::HidGadgetCounts counts = stick.counts();
	r_report.info(p_label + ": the gadget moved " + std::to_string(counts.inputs) + " input and " +
			std::to_string(counts.outputs) + " output reports, " + std::to_string(counts.get_reports) + " GET_REPORT, " +
			std::to_string(counts.set_reports) + " SET_REPORT");
	system.stop();
	system.close_device();
	r_report.info(p_label + ": closed");
	stick.destroy();
	r_report.info(p_label + ": gadget removed");
}

} // namespace

int run_pid_usb() {
	Report report("pid-usb");
	report.info("Linux " + kernel_release());
	// Linux 6.1's hid-pidff needs a Start Delay; newer ones take AJ's descriptor as it is.
	run_stick(report, pid::ScriptedFirmware::AJ, !kernel_older_than(6, 12), "AJ");
	run_stick(report, pid::ScriptedFirmware::AJ_START_DELAY, true, "AJ with a Start Delay");
	return report.failed();
}

} // namespace haptics::vm
