// Godot's own SDL and ours on one DualSense (issue 38, item 6): a uhid DualSense hid-playstation
// binds; our DualSense backend drives it over hidraw with the hand pressed into a floor (trigger
// resistance, lightbar, player LED), and a second process runs Debian's libSDL3 as Godot 4.6
// runs it (sdl_godot.h), whose HIDAPI PS5 driver opens the same hidraw node and writes its own
// output reports. Every report that reaches the pad is counted by who sent it (ours and the
// kernel's are 63 bytes, SDL's 48: SDL_hidapi_ps5.c) and by what it sets. Checked: SDL opens the
// pad through HIDAPI and writes to it, never sets a trigger bit, and the triggers hold our
// effect through SDL's open, a vibration the game asks Godot for, SDL's exit, and an SDL that
// had the pad before our backend opened it; with SDL_JOYSTICK_HIDAPI_PS5=0 no report of SDL's
// reaches the pad. The motors are left to SDL while our backend has no rumble of its own: no
// report of ours sets their bits, and the game's 1 s vibration is held by the pad for its
// whole second. The lightbar and player LEDs, which both write, are reported in numbers
// (docs/linux-kernel.md, "Godot's SDL beside ours").

#include "dev_tools/uhid/dualsense_uhid.h"
#include "devices/dualsense/dualsense_backend.h"
#include "devices/dualsense/dualsense_mapping.h"
#include "devices/dualsense/dualsense_triggers.h"
#include "rig.h"
#include "scenarios.h"
#include "sdl_godot.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <memory>
#include <set>
#include <thread>
#include <vector>

namespace haptics::vm {

namespace {

using dualsense::TriggerEffect;
namespace common = dualsense::common;

constexpr size_t SDL_USB_REPORT_SIZE = 48; // SDL_hidapi_ps5.c: the ID and the 47-byte block.
constexpr uint8_t FLAG0_RUMBLE = dualsense::FLAG0_COMPATIBLE_VIBRATION | dualsense::FLAG0_HAPTICS_SELECT;
constexpr uint8_t FLAG0_TRIGGERS = dualsense::FLAG0_RIGHT_TRIGGER | dualsense::FLAG0_LEFT_TRIGGER;
constexpr uint8_t FLAG1_LIGHTS = dualsense::FLAG1_LIGHTBAR | dualsense::FLAG1_PLAYER_LEDS;

// What reached the pad in one stretch, by sender.
struct Tally {
	int ours = 0; // 63 bytes: our backend (hid-playstation sends none while nobody drives its node).
	int sdl = 0;
	int sdl_trigger = 0; // SDL reports with a trigger bit.
	int sdl_rumble = 0; // ... with rumble bits and a motor byte set.
	int sdl_lights = 0; // ... with the lightbar or player-LED bits.
	int ours_motors_zero_after_sdl = 0; // Ours stating motors 0 after SDL's first rumble.
	int ours_cutting_sdl = 0; // ... of those, before SDL's own next report (its rumble's end).
	int ours_motor_bits = 0; // Ours with a motor valid bit (flag0 bits 0-1, flag2 bit 2).
	int ours_motor_bits_in_sdl_rumble = 0; // ... between SDL's rumble and SDL's next report.
	int ours_trigger = 0; // Ours with the trigger bits.
	TriggerEffect our_block; // The R2 block of the newest of those.
	uint8_t sdl_motor_left = 0;
	uint8_t sdl_motor_right = 0;
	std::set<std::string> sdl_flags; // "flag0/flag1/flag2" of each SDL report.
	std::vector<uint8_t> last_sdl_lights;
	std::vector<uint8_t> first_sdl_rumble;
};

Tally tally(const uhid::DualSenseUhidPad &p_pad) {
	Tally result;
	bool sdl_rumbled = false;
	bool sdl_spoke_since = false;
	for (const std::vector<uint8_t> &report : p_pad.outputs()) {
		if (report.size() < SDL_USB_REPORT_SIZE || report[0] != dualsense::USB_OUTPUT_REPORT_ID) {
			continue;
		}
		const uint8_t *block = report.data() + dualsense::USB_COMMON_OFFSET;
		const uint8_t flag0 = block[common::VALID_FLAG0];
		const bool motors = block[common::MOTOR_LEFT] != 0 || block[common::MOTOR_RIGHT] != 0;
		if (report.size() != SDL_USB_REPORT_SIZE) {
			++result.ours;
			const bool motor_bits =
					(flag0 & FLAG0_RUMBLE) != 0 || (block[common::VALID_FLAG2] & dualsense::FLAG2_COMPATIBLE_VIBRATION2) != 0;
			result.ours_motor_bits += motor_bits;
			result.ours_motor_bits_in_sdl_rumble += motor_bits && sdl_rumbled && !sdl_spoke_since;
			const bool zeroes = sdl_rumbled && (flag0 & FLAG0_RUMBLE) != 0 && !motors;
			result.ours_motors_zero_after_sdl += zeroes;
			result.ours_cutting_sdl += zeroes && !sdl_spoke_since;
			if ((flag0 & FLAG0_TRIGGERS) == FLAG0_TRIGGERS) {
				++result.ours_trigger;
				std::copy_n(block + common::RIGHT_TRIGGER, dualsense::TRIGGER_BLOCK_SIZE, result.our_block.bytes);
			}
			continue;
		}
		++result.sdl;
		sdl_spoke_since = sdl_rumbled;
		char flags[16];
		std::snprintf(flags, sizeof(flags), "%02x/%02x/%02x", flag0, block[common::VALID_FLAG1], block[common::VALID_FLAG2]);
		result.sdl_flags.insert(flags);
		result.sdl_trigger += (flag0 & FLAG0_TRIGGERS) != 0;
		if ((block[common::VALID_FLAG1] & FLAG1_LIGHTS) != 0) {
			++result.sdl_lights;
			result.last_sdl_lights = report;
		}
		const bool rumble = ((flag0 & dualsense::FLAG0_COMPATIBLE_VIBRATION) != 0 ||
									(block[common::VALID_FLAG2] & dualsense::FLAG2_COMPATIBLE_VIBRATION2) != 0) &&
				motors;
		if (rumble) {
			result.first_sdl_rumble = sdl_rumbled ? result.first_sdl_rumble : report;
			sdl_spoke_since = sdl_rumbled;
			sdl_rumbled = true;
			++result.sdl_rumble;
			result.sdl_motor_left = std::max(result.sdl_motor_left, block[common::MOTOR_LEFT]);
			result.sdl_motor_right = std::max(result.sdl_motor_right, block[common::MOTOR_RIGHT]);
		}
	}
	return result;
}

std::string describe(const Tally &p_tally) {
	std::string flags;
	for (const std::string &flag : p_tally.sdl_flags) {
		flags += (flags.empty() ? "" : " ") + flag;
	}
	char text[400];
	std::snprintf(text, sizeof(text),
			"%d of ours (%d with motor bits), %d of SDL's (valid flags 0/1/2: %s; with trigger bits %d, lights %d, rumble %d, "
			"motors up to %u/%u); ours stating motors 0 after SDL's rumble %d, %d of them before SDL's own next report",
			p_tally.ours, p_tally.ours_motor_bits, p_tally.sdl, flags.empty() ? "-" : flags.c_str(), p_tally.sdl_trigger,
			p_tally.sdl_lights, p_tally.sdl_rumble, p_tally.sdl_motor_left, p_tally.sdl_motor_right,
			p_tally.ours_motors_zero_after_sdl, p_tally.ours_cutting_sdl);
	return text;
}

// Both triggers hold the block of our newest trigger report, a real resistance, the one they
// held with ours alone (the hand stays pressed), and SDL set no trigger bit.
bool triggers_ours(Report &r_report, uhid::DualSenseUhidPad &p_pad, const Tally &p_tally, const TriggerEffect &p_alone,
		const std::string &p_when) {
	const dualsense::ScriptedPadHeld held = p_pad.pad().held();
	r_report.wire(p_when + ": R2 block the pad holds", held.right_trigger.bytes);
	return r_report.check(p_tally.ours_trigger >= 1 && dualsense::trigger_feedback_strength(held.right_trigger) >= 3 &&
					held.right_trigger == p_tally.our_block && held.left_trigger == p_tally.our_block &&
					held.right_trigger == p_alone && p_tally.sdl_trigger == 0,
			p_when + ": both triggers hold the resistance of our newest trigger report (strength " +
					std::to_string(dualsense::trigger_feedback_strength(held.right_trigger)) + ", " +
					std::to_string(p_tally.ours_trigger) + " such reports), as with ours alone; no trigger bit from SDL");
}

// The game's frames until the child opened the pad or p_seconds passed.
bool frames_until_opened(HapticsSystem *p_system, const GodotSdlProcess &p_sdl, GodotSdlJoypad &r_joypad, double p_seconds) {
	const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(p_seconds);
	while (!p_sdl.opened(dualsense::SONY_VENDOR_ID, dualsense::DUALSENSE_PRODUCT_ID, r_joypad)) {
		if (std::chrono::steady_clock::now() > deadline) {
			return false;
		}
		if (p_system != nullptr) {
			stand_on_floor(*p_system, 0.1);
		} else {
			std::this_thread::sleep_for(std::chrono::milliseconds(100));
		}
	}
	return true;
}

// Starts the SDL process (with p_hints) and waits for it to open the pad: through its HIDAPI
// driver on hidraw, or (p_hidapi false) on hid-playstation's event node.
bool start_godot_sdl(Report &r_report, GodotSdlProcess &r_sdl, HapticsSystem *p_system, const std::string &p_when,
		const std::vector<std::string> &p_hints = {}, bool p_hidapi = true) {
	const Status started = r_sdl.start(p_hints);
	GodotSdlJoypad joypad;
	const bool opened = started.ok() && frames_until_opened(p_system, r_sdl, joypad, 30.0);
	std::string version = "-";
	(void)r_sdl.initialised(version);
	for (const std::string &line : r_sdl.lines()) {
		r_report.info(p_when + ": SDL process: " + line);
	}
	return r_report.check(opened && joypad.gamepad && joypad.hidapi == p_hidapi,
			p_when + ": libSDL3 " + version + ", initialised as Godot does, opened the DualSense as a gamepad " +
					(p_hidapi ? "through its HIDAPI driver" : "on hid-playstation's event node") + " (player " +
					std::to_string(joypad.player) + ", rumble " + std::to_string(joypad.rumble) + ") " + started.message());
}

// Stands on the floor for p_seconds while stamping each report reaching the pad with when it
// arrived (sampled every 5 ms): r_stamps[i] for p_pad.outputs()[i].
void stand_stamping(uhid::DualSenseUhidPad &p_pad, HapticsSystem &r_system, double p_seconds, std::vector<double> &r_stamps) {
	r_stamps.assign(p_pad.outputs().size(), 0.0);
	std::atomic<bool> sampling{ true };
	const auto start = std::chrono::steady_clock::now();
	std::thread sampler([&] {
		while (sampling.load(std::memory_order_acquire)) {
			const size_t count = p_pad.outputs().size();
			const double at = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
			r_stamps.resize(std::max(r_stamps.size(), count), at);
			std::this_thread::sleep_for(std::chrono::milliseconds(5));
		}
	});
	stand_on_floor(r_system, p_seconds);
	sampling.store(false, std::memory_order_release);
	sampler.join();
}

// How long SDL's first rumble held on the wire: from its report to the next that ends it (one
// of SDL's without it, or one of ours with a motor bit); -1 when there was none. r_ended_by_ours: that report was ours.
double sdl_rumble_on_wire_s(const std::vector<std::vector<uint8_t>> &p_outputs, const std::vector<double> &p_stamps,
		bool &r_ended_by_ours) {
	double began = -1.0;
	for (size_t i = 0; i < p_outputs.size() && i < p_stamps.size(); ++i) {
		const std::vector<uint8_t> &report = p_outputs[i];
		if (report.size() < SDL_USB_REPORT_SIZE || report[0] != dualsense::USB_OUTPUT_REPORT_ID) {
			continue;
		}
		const uint8_t *block = report.data() + dualsense::USB_COMMON_OFFSET;
		const bool bits = (block[common::VALID_FLAG0] & FLAG0_RUMBLE) != 0 ||
				(block[common::VALID_FLAG2] & dualsense::FLAG2_COMPATIBLE_VIBRATION2) != 0;
		const bool sdl = report.size() == SDL_USB_REPORT_SIZE;
		const bool rumbles = bits && block[common::MOTOR_LEFT] != 0;
		if (began < 0.0) {
			began = sdl && rumbles ? p_stamps[i] : began;
		} else if (sdl ? !rumbles : bits) {
			r_ended_by_ours = !sdl;
			return p_stamps[i] - began;
		}
	}
	return -1.0;
}

bool open_ours(Report &r_report, HapticsSystem &r_system, const std::string &p_when) {
	DeviceInfo info;
	double max_force_n = 0.0;
	return r_report.check(find_listed(dualsense::SONY_VENDOR_ID, dualsense::DUALSENSE_PRODUCT_ID, BACKEND_HIDAPI, info, 8.0) &&
						   info.driver == DRIVER_DUALSENSE,
				   p_when + ": our DualSense backend lists the pad") &&
			open_and_run(r_report, info, r_system, max_force_n, p_when);
}

// Ours first, then SDL opens the pad, the game vibrates it through Godot, SDL quits.
void ours_then_sdl(Report &r_report, uhid::DualSenseUhidPad &p_pad, HapticsSystem &r_system, TriggerEffect &r_alone) {
	p_pad.pad().set_stick_deflection(0.0, -0.6); // Pushed down: the hand presses into the floor.
	stand_on_floor(r_system, 1.0);
	p_pad.clear_outputs();
	stand_on_floor(r_system, 1.5);
	const Tally alone = tally(p_pad);
	r_alone = p_pad.pad().held().right_trigger;
	r_report.info("ours alone, 1.5 s: " + describe(alone));
	triggers_ours(r_report, p_pad, alone, r_alone, "ours alone");

	const size_t asked_before = p_pad.features_asked().size();
	p_pad.clear_outputs();
	GodotSdlProcess sdl;
	if (!start_godot_sdl(r_report, sdl, &r_system, "SDL opens the pad")) {
		return;
	}
	stand_on_floor(r_system, 1.5);
	const std::vector<uint8_t> asked = p_pad.features_asked();
	r_report.info("SDL opens the pad: it read feature reports " +
			hex(std::vector<uint8_t>(asked.begin() + static_cast<std::ptrdiff_t>(asked_before), asked.end())));
	const Tally opened = tally(p_pad);
	r_report.info("SDL opens the pad: " + describe(opened));
	r_report.wire("SDL opens the pad: SDL's last report with lights", opened.last_sdl_lights);
	r_report.check(opened.sdl >= 1, "SDL opens the pad: SDL wrote its own output reports to it (" + std::to_string(opened.sdl) + ")");
	triggers_ours(r_report, p_pad, opened, r_alone, "SDL opens the pad");
	const dualsense::ScriptedPadHeld lights = p_pad.pad().held();
	r_report.check(lights.lightbar == dualsense::LIGHTBAR_CONTACT && lights.player_leds == dualsense::PLAYER_LEDS_SESSION,
			"SDL opens the pad: within our 0.5 s keep-alive the lightbar and player LED are ours again");

	p_pad.clear_outputs();
	sdl.vibrate(dualsense::SONY_VENDOR_ID, dualsense::DUALSENSE_PRODUCT_ID, 0.5, 1.0, 1.0);
	std::vector<double> stamps;
	stand_stamping(p_pad, r_system, 2.5, stamps);
	const Tally vibrated = tally(p_pad);
	bool ended_by_ours = false;
	const double on_wire_s = sdl_rumble_on_wire_s(p_pad.outputs(), stamps, ended_by_ours);
	r_report.info("Input.start_joy_vibration(weak 0.5, strong 1.0, 1 s) through Godot's SDL, 2.5 s: " + describe(vibrated));
	r_report.wire("vibration: SDL's first rumble report", vibrated.first_sdl_rumble);
	r_report.check(vibrated.sdl_rumble >= 1 && vibrated.sdl_motor_left > 0,
			"vibration: SDL's rumble reached the motors (strong motor byte " + std::to_string(vibrated.sdl_motor_left) + ")");
	r_report.check(vibrated.ours >= 2 && vibrated.ours_motor_bits == 0 && vibrated.ours_motor_bits_in_sdl_rumble == 0 &&
					vibrated.ours_cutting_sdl == 0,
			"vibration: none of our " + std::to_string(vibrated.ours) +
					" reports set a motor bit (our backend has no rumble of its own), so none cut SDL's short");
	char length[96];
	std::snprintf(length, sizeof(length), "%.3f s, ended by %s", on_wire_s, ended_by_ours ? "ours" : "SDL's own report");
	r_report.check(on_wire_s >= 0.9 && on_wire_s <= 1.5 && !ended_by_ours,
			std::string("vibration: SDL's rumble held on the wire for the second the game asked (") + length + ")");
	triggers_ours(r_report, p_pad, vibrated, r_alone, "vibration");

	p_pad.clear_outputs();
	r_report.check(sdl.stop(), "SDL quits: the SDL process closed its joypads and quit SDL");
	stand_on_floor(r_system, 1.0);
	const Tally quit = tally(p_pad);
	r_report.info("SDL quits, 1 s: " + describe(quit));
	triggers_ours(r_report, p_pad, quit, r_alone, "SDL quits");
}

// The hint that keeps SDL's HIDAPI driver off the pad: SDL takes hid-playstation's event node.
void hint_keeps_sdl_off(Report &r_report, uhid::DualSenseUhidPad &p_pad, HapticsSystem &r_system, const TriggerEffect &p_alone) {
	p_pad.clear_outputs();
	GodotSdlProcess sdl;
	if (start_godot_sdl(r_report, sdl, &r_system, "SDL_JOYSTICK_HIDAPI_PS5=0", { "SDL_JOYSTICK_HIDAPI_PS5=0" }, false)) {
		stand_on_floor(r_system, 1.0);
		const Tally kept = tally(p_pad);
		r_report.info("SDL_JOYSTICK_HIDAPI_PS5=0: " + describe(kept));
		r_report.check(kept.sdl == 0, "SDL_JOYSTICK_HIDAPI_PS5=0: no report of SDL's reached the pad");
		triggers_ours(r_report, p_pad, kept, p_alone, "SDL_JOYSTICK_HIDAPI_PS5=0");
	}
	r_report.check(sdl.stop(), "SDL_JOYSTICK_HIDAPI_PS5=0: the SDL process quit");
}

// SDL had the pad first (Godot opens joypads at start-up, before a scene opens our device).
void sdl_then_ours(Report &r_report, uhid::DualSenseUhidPad &p_pad, HapticsSystem &r_system, const TriggerEffect &p_alone) {
	GodotSdlProcess sdl;
	if (!start_godot_sdl(r_report, sdl, nullptr, "SDL first")) {
		return;
	}
	p_pad.clear_outputs();
	if (open_ours(r_report, r_system, "SDL first, then ours")) {
		stand_on_floor(r_system, 1.5);
		const Tally both = tally(p_pad);
		r_report.info("SDL first, then ours, 1.5 s: " + describe(both));
		triggers_ours(r_report, p_pad, both, p_alone, "SDL first, then ours");
	}
	r_report.check(sdl.stop(), "SDL first: the SDL process quit");
	r_system.stop();
	r_system.close_device();
}

} // namespace

int run_godot_sdl_dualsense() {
	Report report("godot-sdl-dualsense");
	auto scripted = std::make_shared<dualsense::ScriptedDualSense>();
	uhid::DualSenseUhidPad pad(scripted);
	if (!report.check(pad.plug().ok(), "a uhid DualSense hid-playstation binds")) {
		return report.failed();
	}
	HapticsSystem system;
	TriggerEffect alone;
	if (open_ours(report, system, "ours")) {
		ours_then_sdl(report, pad, system, alone);
		hint_keeps_sdl_off(report, pad, system, alone);
	}
	system.stop();
	system.close_device();
	const bool off = eventually([&] { return dualsense::trigger_feedback_strength(scripted->held().right_trigger) == 0; }, 2.0);
	report.check(off, "closed: our backend left the triggers off");
	sdl_then_ours(report, pad, system, alone);
	pad.unplug();
	return report.failed();
}

} // namespace haptics::vm
