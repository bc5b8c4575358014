// Godot's own SDL and ours on a force-feedback wheel (issue 38, item 6): a uinput wheel shaped
// as hid-pidff presents a PID wheel (steering on ABS_X; FF_CONSTANT, FF_PERIODIC with a sine,
// FF_GAIN, FF_AUTOCENTER; ff-core adds FF_RUMBLE), driven by our evdev backend with the wheel
// turned into a wall, while a second process runs Debian's libSDL3 as Godot 4.6 runs it
// (sdl_godot.h). Every ff-core request that reaches the wheel is recorded. Checked: SDL opens the
// wheel's event node with rumble and, of its own accord, uploads, plays and erases nothing and
// sets neither gain nor autocentre; when the game asks Godot for a vibration, SDL's rumble is an
// effect of its own beside ours, gone when SDL quits; our constant force plays throughout
// (docs/linux-kernel.md, "Godot's SDL beside ours").

#include "core/render/frame.h"
#include "dev_tools/uinput/uinput_ff_device.h"
#include "rig.h"
#include "scenarios.h"
#include "sdl_godot.h"

#include <sys/stat.h>
#include <sys/sysmacros.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <thread>

namespace haptics::vm {

namespace {

constexpr const char *PHYS = "haptics-uinput/wheel";

evdev::ScriptedEvdevScript pid_wheel_script() {
	evdev::ScriptedEvdevScript script = evdev::scripted_wheel_script();
	script.name = "Scripted PID wheel";
	script.axes = { { evdev::EVDEV_ABS_X, evdev::AbsRange{ 32768, 0, 65535, 0, 0, 0 } } };
	script.ff_codes = { evdev::EVDEV_FF_CONSTANT, evdev::EVDEV_FF_PERIODIC, evdev::EVDEV_FF_SINE, evdev::EVDEV_FF_GAIN,
		evdev::EVDEV_FF_AUTOCENTER };
	return script;
}

// What udevd's input_id records for a wheel on a desktop, which SDL reads through libudev
// (SDL_udev.c: ID_INPUT_JOYSTICK). The VM has no udevd: the test writes the record.
std::string tag_joystick(const std::string &p_event_path) {
	struct stat node {};
	if (::stat(p_event_path.c_str(), &node) != 0) {
		return "";
	}
	::mkdir("/run/udev", 0755);
	::mkdir("/run/udev/data", 0755);
	const std::string path =
			"/run/udev/data/c" + std::to_string(major(node.st_rdev)) + ":" + std::to_string(minor(node.st_rdev));
	std::ofstream(path) << "E:ID_INPUT=1\nE:ID_INPUT_JOYSTICK=1\n";
	return path;
}

// The game's frames: the wheel turned right into a wall (its normal points left).
void press_wall(HapticsSystem &p_system, double p_seconds) {
	Frame frame;
	add_contact(frame, Vec3{ -1.0, 0.0, 0.0 });
	const int count = static_cast<int>(p_seconds * 50.0);
	for (int i = 0; i < count; ++i) {
		frame.sequence = static_cast<uint64_t>(i);
		(void)p_system.submit_frame(frame);
		std::this_thread::sleep_for(std::chrono::milliseconds(20));
	}
}

// What reached the wheel in one stretch: ours (updates of our FF_CONSTANT effect) and anyone's else.
struct FfTally {
	int ours = 0;
	int other_uploads = 0;
	int other_plays = 0;
	int other_erases = 0;
	int our_erases = 0;
	int gains = 0;
	int autocenters = 0;
	uinput::UinputRecord other; // The first upload not ours.
	int peak_magnitude = 0; // The largest periodic magnitude of those.
};

FfTally tally(const uinput::UinputFfDevice &p_wheel, int16_t p_our_id) {
	FfTally result;
	for (const uinput::UinputRecord &record : p_wheel.records()) {
		const bool ours = record.id == p_our_id;
		switch (record.kind) {
			case uinput::UinputRecord::Kind::UPLOAD:
				if (ours && record.effect.type == evdev::EVDEV_FF_CONSTANT) {
					++result.ours;
				} else {
					result.other = result.other_uploads++ == 0 ? record : result.other;
					result.peak_magnitude = std::max<int>(result.peak_magnitude, std::abs(record.effect.periodic_magnitude));
				}
				break;
			case uinput::UinputRecord::Kind::PLAY:
				result.other_plays += !ours;
				break;
			case uinput::UinputRecord::Kind::ERASE:
				(ours ? result.our_erases : result.other_erases)++;
				break;
			case uinput::UinputRecord::Kind::GAIN:
				++result.gains;
				break;
			case uinput::UinputRecord::Kind::AUTOCENTER:
				++result.autocenters;
				break;
		}
	}
	return result;
}

std::string describe(const FfTally &p_tally) {
	char text[320];
	std::snprintf(text, sizeof(text),
			"%d updates of our effect; others: %d uploads (first: id %d type 0x%02x waveform 0x%02x period %u ms length %u ms; "
			"peak magnitude %d), %d plays, %d erases; %d erases of ours, %d FF_GAIN, %d FF_AUTOCENTER",
			p_tally.ours, p_tally.other_uploads, p_tally.other.id, p_tally.other.effect.type,
			p_tally.other.effect.periodic_waveform, p_tally.other.effect.periodic_period_ms,
			p_tally.other.effect.replay_length_ms, p_tally.peak_magnitude, p_tally.other_plays, p_tally.other_erases, p_tally.our_erases,
			p_tally.gains, p_tally.autocenters);
	return text;
}

// Our constant force is what the wheel plays, and it pushes the hand out of the wall.
bool ours_plays(Report &r_report, const uinput::UinputFfDevice &p_wheel, const HapticsSystem &p_system,
		double p_max_force_n, const std::string &p_when) {
	const Vec3 servo = p_system.forces().total;
	const Vec3 played{ p_wheel.rendered().axis_x * p_max_force_n, servo.y, 0.0 };
	return r_report.check(servo.x < -0.3 && p_wheel.rendered().playing == 1 &&
					same_force(r_report, Vec3{ servo.x, servo.y, 0.0 }, played, 0.02 * p_max_force_n, p_when),
			p_when + ": the wheel plays our constant force");
}

} // namespace

int run_godot_sdl_wheel() {
	Report report("godot-sdl-wheel");
	const evdev::ScriptedEvdevScript script = pid_wheel_script();
	uinput::UinputFfDevice wheel(script);
	const Status created = wheel.create(PHYS);
	const std::string record = created ? tag_joystick(wheel.event_path()) : "";
	if (!report.check(created.ok() && !record.empty(),
				"a uinput PID wheel at " + wheel.event_path() + ", udev's joystick record at " + record + " " + created.message())) {
		return report.failed();
	}
	DeviceInfo info;
	HapticsSystem system;
	double max_force_n = 0.0;
	if (!report.check(find_listed(script.vendor, script.product, BACKEND_EVDEV, info, 5.0), "our evdev backend lists the wheel") ||
			!open_and_run(report, info, system, max_force_n, "ours")) {
		return report.failed();
	}
	(void)wheel.set_stick_axes(0.6, 0.0);
	press_wall(system, 1.0);
	uinput::UinputRecord ours;
	const int16_t our_id = wheel.last_upload(evdev::EVDEV_FF_CONSTANT, ours) ? ours.id : -1;
	wheel.clear_records();
	press_wall(system, 1.5);
	report.info("ours alone, 1.5 s: " + describe(tally(wheel, our_id)));
	ours_plays(report, wheel, system, max_force_n, "ours alone");

	GodotSdlProcess sdl;
	const Status started = sdl.start();
	GodotSdlJoypad joypad;
	const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
	while (started.ok() && !sdl.opened(script.vendor, script.product, joypad) && std::chrono::steady_clock::now() < deadline) {
		press_wall(system, 0.1);
	}
	for (const std::string &line : sdl.lines()) {
		report.info("SDL process: " + line);
	}
	if (report.check(sdl.opened(script.vendor, script.product, joypad) && !joypad.hidapi && joypad.rumble,
				std::string("SDL, initialised as Godot does, opened the wheel's event node (") +
						(joypad.gamepad ? "as a gamepad" : "as a joystick") + ", with rumble) " + started.message())) {
		press_wall(system, 1.5);
		const FfTally opened = tally(wheel, our_id);
		report.info("SDL opens the wheel, up to 1.5 s after: " + describe(opened));
		report.check(opened.other_uploads == 0 && opened.other_plays == 0 && opened.other_erases == 0 && opened.our_erases == 0 &&
						opened.gains == 0 && opened.autocenters == 0,
				"SDL opens the wheel: no upload, play, erase, gain or autocentre of SDL's reached it");
		ours_plays(report, wheel, system, max_force_n, "SDL opens the wheel");

		wheel.clear_records();
		sdl.vibrate(script.vendor, script.product, 0.5, 1.0, 1.0);
		press_wall(system, 0.5);
		const evdev::ScriptedRenderedForce during = wheel.rendered();
		press_wall(system, 1.5);
		const FfTally vibrated = tally(wheel, our_id);
		report.info("Input.start_joy_vibration(weak 0.5, strong 1.0, 1 s) through Godot's SDL, 2 s: " + describe(vibrated));
		report.wire("vibration: SDL's first upload as the wheel got it", vibrated.other.bytes);
		report.check(vibrated.other_uploads >= 1 && vibrated.other_plays >= 1 && vibrated.other.id != our_id &&
						vibrated.our_erases == 0 && during.playing == 1 && during.periodic_playing + during.rumbles_playing >= 1,
				"vibration: SDL's rumble is an effect of its own (id " + std::to_string(vibrated.other.id) +
						"), playing beside our constant force, which stays");
		ours_plays(report, wheel, system, max_force_n, "vibration");

		wheel.clear_records();
		report.check(sdl.stop(), "SDL quits: the SDL process closed its joypads and quit SDL");
		press_wall(system, 0.5);
		const FfTally quit = tally(wheel, our_id);
		report.info("SDL quits: " + describe(quit));
		report.check(quit.our_erases == 0 && wheel.rendered().periodic_playing == 0 && wheel.rendered().rumbles_playing == 0,
				"SDL quits: its effect is gone, ours is not");
		ours_plays(report, wheel, system, max_force_n, "SDL quits");
	}
	(void)sdl.stop();
	system.stop();
	system.close_device();
	wheel.destroy();
	std::remove(record.c_str());
	return report.failed();
}

} // namespace haptics::vm
