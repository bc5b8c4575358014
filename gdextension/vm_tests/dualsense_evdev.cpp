// The DualSense's gamepad node that hid-playstation makes (rumble through ff-memless), driven
// by our evdev backend: listed by the evdev enumeration, opened as a vibration device, and an
// impact the servo renders goes through EVIOCSFF, ff-memless and hid-playstation to the pad as
// output report 0x02 with the motor bytes of what we uploaded.

#include "dev_tools/uhid/dualsense_uhid.h"
#include "devices/dualsense/dualsense_backend.h"
#include "devices/evdev/evdev_backend.h"
#include "recording_syscalls.h"
#include "rig.h"
#include "scenarios.h"
#include "system/haptics_system.h"

#include <algorithm>
#include <cstdio>
#include <memory>

namespace haptics::vm {

namespace {

struct KernelRumble {
	std::vector<uint8_t> report;
	uint8_t left = 0; // Strong motor.
	uint8_t right = 0; // Weak motor.
};

// The kernel's rumble reports (hid-playstation sets haptics-select and a rumble recipe).
std::vector<KernelRumble> kernel_rumbles(const uhid::DualSenseUhidPad &p_pad) {
	std::vector<KernelRumble> rumbles;
	for (const std::vector<uint8_t> &report : p_pad.outputs()) {
		if (report.size() < dualsense::USB_OUTPUT_SIZE || report[0] != dualsense::USB_OUTPUT_REPORT_ID) {
			continue;
		}
		const uint8_t *common = report.data() + dualsense::USB_COMMON_OFFSET;
		const bool rumble = (common[dualsense::common::VALID_FLAG0] & dualsense::FLAG0_HAPTICS_SELECT) != 0 &&
				((common[dualsense::common::VALID_FLAG0] & dualsense::FLAG0_COMPATIBLE_VIBRATION) != 0 ||
						(common[dualsense::common::VALID_FLAG2] & dualsense::FLAG2_COMPATIBLE_VIBRATION2) != 0);
		if (rumble) {
			rumbles.push_back({ report, common[dualsense::common::MOTOR_LEFT], common[dualsense::common::MOTOR_RIGHT] });
		}
	}
	return rumbles;
}

} // namespace

void run_dualsense_evdev(Report &r_report, uhid::DualSenseUhidPad &p_pad) {
	DeviceInfo info;
	const bool listed = find_listed(dualsense::SONY_VENDOR_ID, dualsense::DUALSENSE_PRODUCT_ID, BACKEND_EVDEV, info, 8.0);
	if (!r_report.check(listed, "evdev: list_all_devices() finds hid-playstation's gamepad node")) {
		return;
	}
	r_report.info("evdev: " + info.id + " at " + info.path + " '" + info.product + "', driver '" + info.driver + "', " +
			(info.openable ? "openable" : "not openable: " + info.unavailable_reason));
	r_report.check(info.driver == DRIVER_EVDEV && info.openable, "evdev: the evdev backend drives it");

	auto sys = std::make_shared<RecordingEvdevSyscalls>();
	auto device = std::make_unique<evdev::EvdevDevice>(sys, evdev::device_config_for(info));
	const Status opened = device->open();
	if (!r_report.check(opened.ok(), std::string("evdev: our backend opens it ") + opened.message())) {
		return;
	}
	const evdev::EvdevFfFeatures features = device->features();
	r_report.check(features.rumble && features.periodic && features.gain && !features.constant,
			"evdev: EV_FF as hid-playstation and ff-memless offer it: " + evdev::describe_ff_features(features));
	r_report.check(device->output() == evdev::EvdevOutput::RUMBLE && device->capabilities().output == ForceOutput::VIBRATION,
			"evdev: opened as a vibration device (one FF_RUMBLE effect)");

	HapticsSystem system;
	const Status engine_opened = system.open_device(std::move(device));
	const Status started = system.start(1000.0);
	if (!r_report.check(engine_opened.ok() && started.ok(),
				std::string("evdev: the servo runs it ") + engine_opened.message() + started.message())) {
		return;
	}
	p_pad.pad().set_stick_deflection(0.0, 0.0);
	stand_on_floor(system, 0.3);
	p_pad.clear_outputs();
	ImpactEvent impact;
	impact.direction = Vec3{ 0.0, 1.0, 0.0 };
	impact.speed_m_per_s = 6.0; // 3 N: the servo's impact cap, full rumble.
	(void)system.push_impact(impact);
	stand_on_floor(system, 0.5);

	const std::vector<KernelRumble> rumbles = kernel_rumbles(p_pad);
	const std::vector<evdev::FfEffectFields> uploads = sys->uploads();
	const auto strongest = std::max_element(rumbles.begin(), rumbles.end(),
			[](const KernelRumble &p_a, const KernelRumble &p_b) { return std::max(p_a.left, p_a.right) < std::max(p_b.left, p_b.right); });
	if (!r_report.check(strongest != rumbles.end() && strongest->right > 0,
				"evdev: the impact reached the pad as output report 0x02 with the motor bytes set")) {
		return;
	}
	r_report.wire("evdev: strongest rumble report from hid-playstation", strongest->report);
	// ff-memless merges updates, so the pad sees some of ours, each as strong / 256, weak / 256.
	size_t matched = 0;
	for (const KernelRumble &rumble : rumbles) {
		const bool ours = std::any_of(uploads.begin(), uploads.end(), [&](const evdev::FfEffectFields &p_upload) {
			return p_upload.type == evdev::EVDEV_FF_RUMBLE && p_upload.rumble_strong / 256 == rumble.left &&
					p_upload.rumble_weak / 256 == rumble.right;
		});
		matched += ours ? 1 : 0;
	}
	char text[200];
	std::snprintf(text, sizeof(text),
			"evdev: each of the pad's %zu rumble reports has the motor bytes of one of our %zu uploads (strong/256 left, weak/256 right): %zu do; peak %u/%u",
			rumbles.size(), uploads.size(), matched, strongest->left, strongest->right);
	r_report.check(matched == rumbles.size() && strongest->right > 64, text);
	const bool quiet = eventually([&] { return p_pad.pad().held().motor_right == 0 && p_pad.pad().held().motor_left == 0; }, 2.0);
	r_report.check(quiet, "evdev: the motors are back at zero once the hit has faded");
	system.stop();
	system.close_device();
}

} // namespace haptics::vm
