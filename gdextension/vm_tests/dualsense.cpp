// A DualSense over USB, end to end against the real kernel: the scripted pad is a uhid device
// the kernel's hid-playstation binds (it reads the pad's feature reports and makes the
// gamepad's evdev node with rumble). Our DualSense backend finds the pad with
// list_all_devices() and drives it over hidraw beside the kernel's driver: a hand pressing
// into a floor becomes trigger resistance, an impact becomes rumble, each as the mapping says
// for the servo's force. The cable is pulled in the middle of that and plugged back. Then our
// evdev backend drives the kernel's gamepad node (dualsense_evdev.cpp).

#include "dev_tools/uhid/dualsense_uhid.h"
#include "devices/dualsense/dualsense_backend.h"
#include "devices/dualsense/dualsense_mapping.h"
#include "rig.h"
#include "scenarios.h"
#include "system/device_factory.h"
#include "system/haptics_system.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

namespace haptics::vm {

namespace {

using dualsense::ScriptedDualSense;

std::string hex_ids(const std::vector<uint8_t> &p_ids) {
	return hex(p_ids);
}

// The newest report our backend sent with trigger blocks (the kernel never sets those bits).
std::vector<uint8_t> last_trigger_report(const uhid::DualSenseUhidPad &p_pad) {
	std::vector<uint8_t> last;
	for (const std::vector<uint8_t> &report : p_pad.outputs()) {
		if (report.size() > 1 && report[0] == dualsense::USB_OUTPUT_REPORT_ID &&
				(report[1] & (dualsense::FLAG0_RIGHT_TRIGGER | dualsense::FLAG0_LEFT_TRIGGER)) != 0) {
			last = report;
		}
	}
	return last;
}

// The report with the strongest motor bytes among those that set the rumble (either recipe).
std::vector<uint8_t> strongest_rumble(const uhid::DualSenseUhidPad &p_pad) {
	std::vector<uint8_t> best;
	int best_motor = -1;
	for (const std::vector<uint8_t> &report : p_pad.outputs()) {
		if (report.size() < dualsense::USB_OUTPUT_SIZE || report[0] != dualsense::USB_OUTPUT_REPORT_ID) {
			continue;
		}
		const uint8_t *common = report.data() + dualsense::USB_COMMON_OFFSET;
		const bool rumble = (common[dualsense::common::VALID_FLAG0] & dualsense::FLAG0_COMPATIBLE_VIBRATION) != 0 ||
				(common[dualsense::common::VALID_FLAG2] & dualsense::FLAG2_COMPATIBLE_VIBRATION2) != 0;
		const int motor = std::max(common[dualsense::common::MOTOR_LEFT], common[dualsense::common::MOTOR_RIGHT]);
		if (rumble && motor > best_motor) {
			best = report;
			best_motor = motor;
		}
	}
	return best;
}

// Opens the listed pad on hidraw and runs the servo on it; false (with the checks saying
// why) when it cannot.
bool open_on_hidraw(Report &r_report, HapticsSystem &p_system, const char *p_when) {
	DeviceInfo info;
	const bool listed = find_listed(dualsense::SONY_VENDOR_ID, dualsense::DUALSENSE_PRODUCT_ID, BACKEND_HIDAPI, info, 8.0);
	if (!r_report.check(listed, std::string(p_when) + ": list_all_devices() finds the pad on hidapi")) {
		return false;
	}
	r_report.info(std::string(p_when) + ": " + info.path + ", driver '" + info.driver + "', " +
			(info.openable ? "openable" : "not openable: " + info.unavailable_reason));
	r_report.check(info.driver == DRIVER_DUALSENSE && info.openable, std::string(p_when) + ": the DualSense backend drives it");
	std::unique_ptr<HapticDevice> device;
	const Status opened = open_listed_device(info, {}, device);
	if (!r_report.check(opened.ok(), std::string(p_when) + ": the factory opens it, hid-playstation bound " + opened.message())) {
		return false;
	}
	const Status engine_opened = p_system.open_device(std::move(device));
	const Status started = p_system.start(1000.0);
	return r_report.check(engine_opened.ok() && started.ok(),
			std::string(p_when) + ": the servo runs it " + engine_opened.message() + started.message());
}

// The hand pressed into the floor: the triggers' resistance on the wire is the mapping's for
// the servo's continuous force.
bool press_into_floor(Report &r_report, uhid::DualSenseUhidPad &p_pad, HapticsSystem &p_system, const char *p_when) {
	p_pad.pad().set_stick_deflection(0.0, 0.0);
	stand_on_floor(p_system, 0.4);
	p_pad.pad().set_stick_deflection(0.0, -0.6); // Pushed down: the hand presses into the floor.
	stand_on_floor(p_system, 1.0);
	const ForceComponents forces = p_system.forces();
	const double continuous_n = length(forces.total - forces.impact);
	dualsense::TriggerMapper mapper;
	const int strength = mapper.update(continuous_n);
	dualsense::TriggerEffect expected = dualsense::trigger_off();
	if (strength > 0) {
		(void)dualsense::trigger_feedback(dualsense::MappingConfig{}.trigger_start_zone, strength, expected);
	}
	const dualsense::ScriptedPadHeld held = p_pad.pad().held();
	char text[160];
	std::snprintf(text, sizeof(text), "%s: servo %.3f N continuous -> trigger strength %d; the pad holds R2 mode 0x%02x strength %d",
			p_when, continuous_n, strength, held.right_trigger.mode(), dualsense::trigger_feedback_strength(held.right_trigger));
	r_report.info(text);
	r_report.wire(std::string(p_when) + ": last output report with trigger blocks", last_trigger_report(p_pad));
	return r_report.check(strength >= 3 && held.right_trigger == expected && held.left_trigger == expected,
			std::string(p_when) + ": both triggers hold the feedback block the mapping gives for the servo's force");
}

// An impact of amplitude p_amplitude_n: the weak motor's bytes peak at what the mapping gives
// for the transients' sampled crest (between 70 % and 100 % of the amplitude), the strong one
// stays off below the knee, and both end at zero.
void knock(Report &r_report, uhid::DualSenseUhidPad &p_pad, HapticsSystem &p_system) {
	constexpr double AMPLITUDE_N = 1.2; // ImpactMaterial gain 0.5 N per m/s at 2.4 m/s.
	p_pad.clear_outputs();
	ImpactEvent impact;
	impact.direction = Vec3{ 0.0, 1.0, 0.0 };
	impact.speed_m_per_s = AMPLITUDE_N / ImpactMaterial{}.gain_n_s_per_m;
	(void)p_system.push_impact(impact);
	stand_on_floor(p_system, 0.4);
	const std::vector<uint8_t> strongest = strongest_rumble(p_pad);
	r_report.wire("impact: strongest rumble report", strongest);
	const double full_scale = dualsense::MappingConfig{}.impact_full_scale_n;
	const int most = static_cast<int>(std::lround(255.0 * AMPLITUDE_N / full_scale));
	const uint8_t right = strongest.empty() ? 0 : strongest[1 + dualsense::common::MOTOR_RIGHT];
	const uint8_t left = strongest.empty() ? 0 : strongest[1 + dualsense::common::MOTOR_LEFT];
	char text[160];
	std::snprintf(text, sizeof(text), "impact %.1f N: weak motor peaked at %u (mapping: at most %d), strong motor %u (below the knee: 0)",
			AMPLITUDE_N, right, most, left);
	r_report.check(right <= most && right >= 0.7 * most && left == 0, text);
	const bool quiet = eventually([&] { return p_pad.pad().held().motor_right == 0 && p_pad.pad().held().motor_left == 0; }, 2.0);
	r_report.check(quiet, "impact: the motors are back at zero once the hit has faded");
}

} // namespace

int run_dualsense() {
	Report report("dualsense");
	auto pad = std::make_shared<ScriptedDualSense>();
	uhid::DualSenseUhidPad device(pad);
	if (!report.check(device.plug().ok(), "the pad is a uhid device")) {
		return report.failed();
	}
	HapticsSystem system;
	if (open_on_hidraw(report, system, "plugged")) {
		const std::vector<uint8_t> asked = device.features_asked();
		const std::vector<uint8_t> kernel_asked(asked.begin(), asked.begin() + std::min<size_t>(asked.size(), 3));
		report.check(kernel_asked == std::vector<uint8_t>{ 0x09, 0x20, 0x05 },
				"hid-playstation read feature reports 09 20 05 (pairing, firmware, calibration); all asked: " + hex_ids(asked));
		press_into_floor(report, device, system, "plugged");
		knock(report, device, system);
	}

	device.unplug(); // In the middle of the session: the hand still pressed into the floor.
	const bool noticed = eventually([&] { return system.device_status().io == DeviceIo::DISCONNECTED; }, 3.0);
	report.check(noticed && system.device_status().reason[0] != '\0',
			std::string("unplugged: the device says DISCONNECTED: ") + system.device_status().reason.c_str());
	const bool stopped = servo_stops(system, 3.0);
	const Status servo = system.servo_status();
	report.check(stopped && servo.code() == StatusCode::DEVICE_DISCONNECTED &&
					std::string(servo.message()).find("zero force") != std::string::npos,
			std::string("unplugged: the servo stopped at zero force: ") + servo.message());
	system.close_device();

	report.check(device.plug().ok(), "replugged");
	if (open_on_hidraw(report, system, "replugged")) {
		press_into_floor(report, device, system, "replugged");
	}
	system.stop();
	system.close_device();
	report.check(eventually([&] { return dualsense::trigger_feedback_strength(pad->held().right_trigger) == 0; }, 2.0),
			"closed: our backend left the triggers off");

	run_dualsense_evdev(report, device);
	device.unplug();
	return report.failed();
}

} // namespace haptics::vm
