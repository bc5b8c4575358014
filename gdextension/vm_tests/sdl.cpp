// The SDL backend end to end against the real kernel, with Debian testing's libSDL3 loaded as
// the game loads it (tools/kernel/initramfs.sh packs it with its libraries) and
// HAPTICS_SDL_ON_LINUX=1 (on Linux the evdev backend drives these devices otherwise):
//  (a) a USB PID stick hid-pidff drives (AJ's firmware with a Start Delay, on a USB gadget):
//      listed by SDL, opened, and the servo's force for a hand pressed into a floor is what
//      hid-pidff puts on the wire (Set Effect, Set Constant Force); held past one effect
//      length it is still rendered (SDL's finite effect, run again);
//  (b) a rumble-only uinput pad (FF_RUMBLE alone, as xpad offers): an impact reaches it as
//      FF_RUMBLE uploads whose magnitudes are SDL's doubled LEFTRIGHT ones;
//  (c) hid-playstation over uhid: SDL reaches the DualSense's gamepad node, and an impact
//      leaves as output report 0x02 with the motor bytes set.
// SDL's haptic API has no input, so for (a) the stick's position reaches the servo from the
// firmware model's own stick (what the player's hand does), around the SDL device.

#include "dev_tools/gadget/hid_gadget.h"
#include "dev_tools/uhid/dualsense_uhid.h"
#include "dev_tools/uhid/pid_uhid.h"
#include "dev_tools/uinput/uinput_ff_device.h"
#include "devices/dualsense/dualsense_backend.h"
#include "devices/dualsense/dualsense_report.h"
#include "devices/sdl/sdl_backend.h"
#include "rig.h"
#include "scenarios.h"
#include "system/device_factory.h"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <thread>

namespace haptics::vm {

namespace {

constexpr uint16_t AJ_VENDOR = 0x2341;
constexpr uint16_t AJ_PRODUCT = 0x8036;
constexpr uint8_t SET_EFFECT = 0x01;
constexpr uint8_t SET_CONSTANT_FORCE = 0x05;
constexpr const char *PAD_NAME = "Microsoft X-Box 360 pad";

// The first SDL entry whose product is p_product, waiting up to p_seconds.
bool find_sdl(const std::string &p_product, DeviceInfo &r_info, double p_seconds = 8.0) {
	return eventually(
			[&] {
				for (const DeviceInfo &info : list_all_devices().devices) {
					if (info.backend == BACKEND_SDL && info.product == p_product) {
						r_info = info;
						return true;
					}
				}
				return false;
			},
			p_seconds);
}

std::string describe(const DeviceInfo &p_info) {
	return p_info.id + ", driver '" + p_info.driver + "', " +
			(p_info.openable ? "openable" : "not openable: " + p_info.unavailable_reason);
}

// The SDL device with a stick: position from the values the test sets on the firmware model.
class WithStick final : public HapticDevice {
public:
	explicit WithStick(std::unique_ptr<HapticDevice> p_device) :
			device_(std::move(p_device)) {}
	void set_stick(double p_x, double p_y) { // Axis frame: +y toward the user.
		x_.store(p_x);
		y_.store(p_y);
	}
	Status open() override { return device_->open(); }
	void close() override { device_->close(); }
	bool is_open() const override { return device_->is_open(); }
	Status calibrate() override { return device_->calibrate(); }
	DeviceCapabilities capabilities() const override {
		DeviceCapabilities capabilities = device_->capabilities();
		capabilities.input_dof = 2;
		return capabilities;
	}
	const char *name() const override { return device_->name(); }
	DeviceStatus status() const override { return device_->status(); }
	DeviceIoStats io_stats() const override { return device_->io_stats(); }
	DeviceIo read_state(DeviceState &r_state) override {
		const DeviceIo io = device_->read_state(r_state);
		const double radius = device_->limits().workspace_radius_m;
		r_state.position_m = Vec3(x_.load() * radius, -y_.load() * radius, 0.0);
		return io;
	}
	DeviceIo write_force(const ForceCommand &p_command) override { return device_->write_force(p_command); }

private:
	std::unique_ptr<HapticDevice> device_;
	std::atomic<double> x_{ 0.0 };
	std::atomic<double> y_{ 0.0 };
};

bool pressed(Report &r_report, pid::ScriptedPidJoystick &p_joystick, WithStick &r_stick, HapticsSystem &r_system,
		double p_x, double p_y, double p_max_force_n, const std::string &p_when) {
	p_joystick.set_stick(p_x, p_y);
	r_stick.set_stick(p_x, p_y);
	stand_on_floor(r_system, 1.0);
	const Vec3 servo = r_system.forces().total;
	r_report.wire(p_when + ": last Set Effect", pid_last_output(p_joystick, SET_EFFECT));
	r_report.wire(p_when + ": last Set Constant Force", pid_last_output(p_joystick, SET_CONSTANT_FORCE));
	r_report.check(length(servo) > 0.3, p_when + ": the servo pushes the hand");
	return same_force(r_report, servo, pid_wire_n(p_joystick, p_max_force_n), 0.03 * p_max_force_n, p_when);
}

void run_pid_stick(Report &r_report) {
	auto joystick = std::make_shared<pid::ScriptedPidJoystick>(pid::ScriptedFirmware::AJ_START_DELAY);
	uhid::PidHidModel model(joystick);
	gadget::HidGadget gadget(model, model);
	gadget::GadgetIdentity identity;
	identity.vendor = AJ_VENDOR;
	identity.product = AJ_PRODUCT;
	identity.manufacturer = "Arduino LLC";
	identity.product_name = "Arduino Leonardo";
	const Status created = gadget.create(identity, joystick->descriptor());
	const Status plugged = created ? gadget.plug() : created;
	if (!r_report.check(plugged.ok(), std::string("stick: a USB gadget hid-pidff drives ") + plugged.message())) {
		return;
	}
	DeviceInfo event;
	DeviceInfo info;
	if (r_report.check(find_listed(AJ_VENDOR, AJ_PRODUCT, BACKEND_EVDEV, event, 8.0), "stick: hid-pidff made its event node") &&
			r_report.check(find_sdl(event.product, info), "stick: SDL lists '" + event.product + "'")) {
		std::this_thread::sleep_for(std::chrono::milliseconds(1500)); // hid-pidff's Pool and Block Load.
		r_report.info("stick: " + describe(info));
		std::unique_ptr<HapticDevice> device;
		const Status opened = open_listed_device(info, {}, device);
		if (r_report.check(opened.ok() && device->capabilities().output == ForceOutput::DIRECTIONAL,
					std::string("stick: the factory opens it through SDL as a directional device ") + opened.message())) {
			const double max_force_n = device->limits().max_force_n;
			auto stick = std::make_unique<WithStick>(std::move(device));
			WithStick &handle = *stick;
			HapticsSystem system;
			const Status engine = system.open_device(std::move(stick));
			const Status started = engine ? system.start(1000.0) : engine;
			if (r_report.check(started.ok(), std::string("stick: the servo runs it at 1 kHz ") + started.message())) {
				pressed(r_report, *joystick, handle, system, 0.0, 0.8, max_force_n, "stick, pressed down");
				pressed(r_report, *joystick, handle, system, -0.6, 0.5, max_force_n, "stick, pressed down and left");
				stand_on_floor(system, 2.0); // Two effect lengths.
				uint16_t duration = 0;
				for (uint8_t block = 1; block <= pid::ScriptedPidJoystick::MAX_EFFECTS; ++block) {
					const pid::ScriptedEffect effect = joystick->effect(block);
					duration = effect.allocated && effect.playing ? effect.duration : duration;
				}
				r_report.info("stick: the playing effect's Duration is " + std::to_string(duration) + " ms");
				r_report.check(duration == sdl::SDL_EFFECT_LENGTH_MS &&
								same_force(r_report, system.forces().total, pid_wire_n(*joystick, max_force_n),
										0.03 * max_force_n, "stick, held 2 s"),
						"stick: a finite effect, run again, still renders the force past two lengths");
				system.stop();
				system.close_device();
				const bool released = eventually([&] { return length(pid_wire_n(*joystick, max_force_n)) < 0.01; }, 2.0);
				r_report.check(released, "stick: closed: the firmware renders no force");
			}
		}
	}
	(void)gadget.unplug();
	gadget.destroy();
}

evdev::ScriptedEvdevScript rumble_pad_script() {
	evdev::ScriptedEvdevScript script;
	script.name = PAD_NAME;
	script.vendor = 0x045e;
	script.product = 0x028e;
	script.ff_codes = { evdev::EVDEV_FF_RUMBLE }; // xpad's: rumble and nothing else.
	const evdev::AbsRange stick{ 0, -32768, 32767, 16, 128, 0 };
	script.axes = { { evdev::EVDEV_ABS_X, stick }, { evdev::EVDEV_ABS_Y, stick } };
	script.key_codes = { evdev::EVDEV_BTN_SOUTH };
	script.max_effects = 16;
	return script;
}

// Opens p_info through the factory and runs the servo; knocks with the servo's strongest impact.
bool knock(Report &r_report, const DeviceInfo &p_info, HapticsSystem &r_system, const std::string &p_when) {
	std::unique_ptr<HapticDevice> device;
	const Status opened = open_listed_device(p_info, {}, device);
	if (!r_report.check(opened.ok() && device->capabilities().output == ForceOutput::VIBRATION,
				p_when + ": the factory opens it through SDL as a vibration device " + opened.message())) {
		return false;
	}
	const Status engine = r_system.open_device(std::move(device));
	const Status started = engine ? r_system.start(1000.0) : engine;
	if (!r_report.check(started.ok(), p_when + ": the servo runs it " + started.message())) {
		return false;
	}
	stand_on_floor(r_system, 0.3);
	ImpactEvent impact;
	impact.direction = Vec3{ 0.0, 1.0, 0.0 };
	impact.speed_m_per_s = 6.0; // 3 N: the servo's impact cap, full rumble.
	(void)r_system.push_impact(impact);
	stand_on_floor(r_system, 0.5);
	return true;
}

void run_rumble_pad(Report &r_report) {
	uinput::UinputFfDevice pad(rumble_pad_script());
	const Status created = pad.create("haptics-uinput/pad");
	DeviceInfo info;
	if (!r_report.check(created.ok(), "pad: a rumble-only uinput pad at " + pad.event_path() + " " + created.message()) ||
			!r_report.check(find_sdl(PAD_NAME, info), "pad: SDL lists it")) {
		return;
	}
	r_report.info("pad: " + describe(info));
	HapticsSystem system;
	if (knock(r_report, info, system, "pad")) {
		uinput::UinputRecord strongest;
		int uploads = 0;
		bool doubled = true;
		for (const uinput::UinputRecord &record : pad.records()) {
			if (record.kind != uinput::UinputRecord::Kind::UPLOAD || record.effect.type != evdev::EVDEV_FF_RUMBLE) {
				continue;
			}
			++uploads;
			// SDL's LEFTRIGHT magnitudes (0..0x7FFF) doubled by its Linux driver.
			doubled = doubled && record.effect.rumble_weak % 2 == 0 && record.effect.rumble_strong % 2 == 0 &&
					record.effect.rumble_strong <= record.effect.rumble_weak && record.effect.replay_length_ms == 1000;
			strongest = record.effect.rumble_weak > strongest.effect.rumble_weak ? record : strongest;
		}
		r_report.wire("pad: strongest FF_RUMBLE upload", strongest.bytes);
		char text[200];
		std::snprintf(text, sizeof(text), "pad: %d FF_RUMBLE uploads, peak weak 0x%04x strong 0x%04x, each an even (doubled) magnitude, strong <= weak, 1000 ms",
				uploads, strongest.effect.rumble_weak, strongest.effect.rumble_strong);
		r_report.check(uploads >= 2 && doubled && strongest.effect.rumble_weak >= 0x8000, text);
		const bool quiet = eventually([&] { return pad.rendered().rumble_weak == 0 && pad.rendered().rumble_strong == 0; }, 2.0);
		r_report.check(quiet, "pad: the motors are back at zero once the hit has faded");
		system.stop();
		system.close_device();
	}
	pad.destroy();
}

void run_playstation(Report &r_report) {
	auto scripted = std::make_shared<dualsense::ScriptedDualSense>();
	uhid::DualSenseUhidPad pad(scripted);
	DeviceInfo info;
	if (!r_report.check(pad.plug().ok(), "dualsense: a uhid pad hid-playstation binds") ||
			!r_report.check(find_sdl("Sony Interactive Entertainment DualSense Wireless Controller", info),
					"dualsense: SDL lists hid-playstation's gamepad node")) {
		return;
	}
	r_report.info("dualsense: " + describe(info));
	HapticsSystem system;
	pad.clear_outputs();
	if (knock(r_report, info, system, "dualsense")) {
		std::vector<uint8_t> strongest;
		int reports = 0;
		for (const std::vector<uint8_t> &report : pad.outputs()) {
			if (report.size() < dualsense::USB_OUTPUT_SIZE || report[0] != dualsense::USB_OUTPUT_REPORT_ID) {
				continue;
			}
			const uint8_t *common = report.data() + dualsense::USB_COMMON_OFFSET;
			const bool rumble = (common[dualsense::common::VALID_FLAG0] & dualsense::FLAG0_HAPTICS_SELECT) != 0;
			reports += rumble ? 1 : 0;
			if (rumble && (strongest.empty() || common[dualsense::common::MOTOR_RIGHT] > strongest[dualsense::USB_COMMON_OFFSET + dualsense::common::MOTOR_RIGHT])) {
				strongest = report;
			}
		}
		r_report.wire("dualsense: strongest rumble report from hid-playstation", strongest);
		const uint8_t right = strongest.empty() ? 0 : strongest[dualsense::USB_COMMON_OFFSET + dualsense::common::MOTOR_RIGHT];
		r_report.check(reports > 0 && right > 64,
				"dualsense: the impact left as output report 0x02 with the motor bytes set (" + std::to_string(reports) +
						" reports, weak motor peak " + std::to_string(right) + ")");
		const bool quiet = eventually([&] { return scripted->held().motor_right == 0 && scripted->held().motor_left == 0; }, 2.0);
		r_report.check(quiet, "dualsense: the motors are back at zero once the hit has faded");
		system.stop();
		system.close_device();
	}
	pad.unplug();
}

} // namespace

int run_sdl() {
	Report report("sdl");
	setenv(sdl::SDL_ON_LINUX_ENV, "1", 1);
	std::string reason;
	sdl::SdlRuntime *runtime = sdl::SdlRuntime::shared(reason);
	if (!report.check(runtime != nullptr, "libSDL3 loads " + reason)) {
		return report.failed();
	}
	run_pid_stick(report);
	run_rumble_pad(report);
	run_playstation(report);
	unsetenv(sdl::SDL_ON_LINUX_ENV);
	return report.failed();
}

} // namespace haptics::vm
