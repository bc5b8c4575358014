// SDL's joysticks in the SDL backend (devices/sdl: sdl_runtime.h "Entries", sdl_backend.h
// "Which backend wins") over a scripted SDL, as on Windows: an XInput pad, which SDL 3 rumbles
// through its joystick API and not its haptics, renders impacts through SDL_RumbleJoystick; a
// DirectInput stick's joystick is its haptic's entry; and a device a specialised backend (raw
// HID PID, DualSense) can open is theirs, listed with the reason and never opened through SDL.

#include "devices/sdl/sdl_backend.h"
#include "sdl_test_support.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cstring>

using namespace haptics;
using namespace haptics::sdl;
using namespace haptics::sdl_test;

namespace {

ScriptedHaptic direct_input_stick() {
	ScriptedHaptic stick = scripted_sdl_stick();
	stick.joystick = true;
	return stick;
}

ScriptedJoystick dualsense() {
	ScriptedJoystick pad;
	pad.name = "DualSense Wireless Controller";
	pad.vendor_id = 0x054c;
	pad.product_id = 0x0ce6;
	return pad;
}

// An entry of another backend as the enumeration has it after its probe.
DeviceInfo other(std::string_view p_driver, const std::string &p_id, uint16_t p_vendor, uint16_t p_product, bool p_openable) {
	DeviceInfo info;
	info.id = p_id;
	info.backend = p_driver == DRIVER_EVDEV ? BACKEND_EVDEV : BACKEND_HIDAPI;
	info.driver = p_driver;
	info.vendor_id = p_vendor;
	info.product_id = p_product;
	info.openable = p_openable;
	return info;
}

std::vector<DeviceInfo> listed(SdlRuntime &r_runtime, std::span<const DeviceInfo> p_others = {}) {
	SdlListOptions options = driving();
	options.claims = sdl_claims(p_others);
	std::vector<DeviceInfo> devices;
	std::vector<std::string> warnings;
	append_sdl_devices(r_runtime, options, devices, warnings);
	CHECK(warnings.empty());
	return devices;
}

SdlDeviceConfig config_for(const std::string &p_key) {
	SdlDeviceConfig config;
	config.key = p_key;
	return config;
}

void hit(SdlHapticDevice &r_device, double p_impact_n, double p_seconds) {
	const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(p_seconds);
	while (std::chrono::steady_clock::now() < end) {
		REQUIRE(r_device.write_force(ForceCommand{ Vec3(), Vec3(0.0, p_impact_n, 0.0) }) == DeviceIo::OK);
		std::this_thread::sleep_for(std::chrono::milliseconds(1));
	}
}

} // namespace

TEST_CASE("sdl joysticks: an XInput pad is a rumble entry, a DirectInput stick's joystick is its haptic's entry with its USB ids") {
	ScriptedJoystick plain = scripted_sdl_xinput_pad();
	plain.name = "Plain stick";
	plain.gamepad = false;
	plain.rumble = false;
	ScriptedSdl sdl({ direct_input_stick() }, { scripted_sdl_xinput_pad(), plain });
	SdlRuntime runtime(ScriptedSdl::api());
	const std::vector<DeviceInfo> devices = listed(runtime);
	REQUIRE(devices.size() == 3); // The stick once (its haptic), the pad, the plain stick.
	CHECK(devices[0].id == "sdl:Arduino LLC Arduino Leonardo#0");
	CHECK(devices[0].vendor_id == 0x2341);
	CHECK(devices[0].product_id == 0x8036);
	CHECK(devices[0].openable);
	CHECK(devices[1].id == "sdl:Xbox 360 Controller#0");
	CHECK(devices[1].vendor_id == 0x045e);
	CHECK(devices[1].openable);
	CHECK(devices[1].driver == DRIVER_SDL);
	CHECK(devices[2].id == "sdl:Plain stick#0");
	CHECK_FALSE(devices[2].openable);
	CHECK(devices[2].unavailable_reason == "SDL offers neither force feedback nor rumble on this joystick");
	// Everything opened to be read was closed again.
	CHECK(sdl.open_references(0) == 0);
	CHECK(sdl.joystick_references(0) == 0);
	CHECK(sdl.joystick_references(1) == 0);
	CHECK(sdl.joystick_subsystem_count() == 1);
	CHECK_FALSE(sdl.joystick_events()); // Nothing drains SDL's event queue.
	CHECK(sdl.hint(SDL_HINT_JOYSTICK_RAWINPUT) == "0"); // The engine's raw input stays its own.
}

TEST_CASE("sdl joysticks: where SDL does not list joysticks (Linux) they stay out, and so does the joystick subsystem") {
	ScriptedSdl sdl({ direct_input_stick() }, { scripted_sdl_xinput_pad() });
	SdlRuntime runtime(ScriptedSdl::api());
	SdlListOptions options;
	options.read = true;
	std::vector<SdlHapticEntry> entries;
	std::string warning;
	REQUIRE(runtime.list(options, entries, warning).ok());
	CHECK(entries.size() == 1);
	CHECK(entries[0].vendor_id == 0);
	CHECK(sdl.joystick_subsystem_count() == 0);
}

TEST_CASE("sdl joysticks: an XInput pad renders impacts through SDL_RumbleJoystick, doubled, renewed, and stopped at close") {
	Rig rig({}, { scripted_sdl_xinput_pad() });
	REQUIRE(rig.entries.size() == 1);
	SdlHapticDevice device(rig.runtime, config_for(rig.entries[0].key));
	REQUIRE(device.open().ok());
	CHECK(device.output() == SdlOutput::JOYSTICK_RUMBLE);
	CHECK(device.capabilities().output == ForceOutput::VIBRATION);
	CHECK(device.capabilities().output_dof == 0);
	CHECK(kinds(rig.sdl.calls()) == std::vector<Kind>{ Kind::JOYSTICK_OPEN });
	hit(device, 3.0, 0.01); // The strongest hit: both motors full.
	REQUIRE(eventually([&] { return !calls_of(rig.sdl.calls(), Kind::JOYSTICK_RUMBLE).empty(); }));
	const ScriptedSdlCall first = calls_of(rig.sdl.calls(), Kind::JOYSTICK_RUMBLE).front();
	CHECK(first.ok);
	CHECK(first.low == 0xfffe); // 0x7FFF doubled, as SDL's Linux driver doubles FF_RUMBLE's.
	CHECK(first.high == 0xfffe);
	CHECK(first.length_ms == SDL_EFFECT_LENGTH_MS);
	rig.sdl.clear_calls();
	hit(device, 1.0, 0.6); // Held: a third of full scale, below the large motor's knee.
	const std::vector<ScriptedSdlCall> rumbles = calls_of(rig.sdl.calls(), Kind::JOYSTICK_RUMBLE);
	REQUIRE(!rumbles.empty());
	// The held level, round(1/3 * 0x7FFF) doubled, sent again at each renewal (0.25 s) while
	// it lasts. Not the last call: a cycle that finds no new impact decays the level, as one
	// between the hold's end and this look did on a loaded machine (Wine, 16732).
	const auto held = std::count_if(rumbles.begin(), rumbles.end(),
			[](const ScriptedSdlCall &p_call) { return p_call.low == 0 && p_call.high == 2 * 10922; });
	CHECK(held >= 2);
	// SDL's joysticks updated with it.
	CHECK(calls_of(rig.sdl.calls(), Kind::JOYSTICK_UPDATE).size() >= 2);
	uint16_t low = 1;
	uint16_t high = 1;
	rig.sdl.clear_calls();
	device.close();
	rig.sdl.joystick_rumble(0, low, high);
	CHECK(low == 0);
	CHECK(high == 0);
	CHECK(kinds(rig.sdl.calls()).back() == Kind::JOYSTICK_CLOSE);
	CHECK(rig.sdl.joystick_references(0) == 0);
	CHECK(rig.runtime.open_count() == 0);
}

TEST_CASE("sdl joysticks: a pad SDL sees go is DISCONNECTED") {
	Rig rig({}, { scripted_sdl_xinput_pad() });
	SdlHapticDevice device(rig.runtime, config_for(rig.entries.at(0).key));
	REQUIRE(device.open().ok());
	rig.sdl.set_joystick_plugged(0, false);
	CHECK(eventually([&] {
		(void)device.write_force(ForceCommand{ Vec3(), Vec3(0.0, 2.0, 0.0) });
		return device.status().io != DeviceIo::OK;
	}));
	CHECK(device.status().io == DeviceIo::DISCONNECTED);
	CHECK(std::strstr(device.status().reason.c_str(), "was unplugged") != nullptr);
	device.close();
	CHECK(rig.sdl.joystick_references(0) == 0);
}

TEST_CASE("sdl joysticks: a pad SDL cannot open says why, in the listing and at open") {
	ScriptedJoystick silent = scripted_sdl_xinput_pad();
	silent.open_error = "XInput: device busy";
	Rig refused({}, { silent });
	REQUIRE(refused.entries.size() == 1);
	CHECK(refused.entries[0].error == "XInput: device busy");
	const Status opened = SdlHapticDevice(refused.runtime, config_for(refused.entries[0].key)).open();
	CHECK(opened.code() == StatusCode::NO_DEVICE);
	CHECK(std::strstr(opened.message(), "XInput: device busy") != nullptr);
}

TEST_CASE("sdl backend: a stick raw HID PID can open is hid-pid's, SDL does not open it, and SDL's entry is offered when hid-pid cannot") {
	const std::string pid_id = "hid:\\\\?\\HID#VID_2341&PID_8036&MI_02#7&1&0000#{4d1e55b2}";
	std::vector<DeviceInfo> others = {
		other(DRIVER_HID_PID, pid_id, 0x2341, 0x8036, true),
		other(DRIVER_DUALSENSE, "hid:dualsense", 0x054c, 0x0ce6, true),
		other(DRIVER_EVDEV, "evdev:pad", 0x045e, 0x028e, true), // Not a claim: evdev's rule is its own.
		other(DRIVER_HID_PID, "hid:unopenable", 0x1234, 0x5678, false), // Not a claim: it cannot open.
	};
	const std::vector<SdlClaim> claims = sdl_claims(others);
	REQUIRE(claims.size() == 2);
	CHECK(claims[0].reason == "driven by the hid-pid backend here: choose its entry (" + pid_id + "), which wins a device both reach");

	ScriptedSdl sdl({ direct_input_stick() }, { scripted_sdl_xinput_pad(), dualsense() });
	SdlRuntime runtime(ScriptedSdl::api());
	std::vector<DeviceInfo> devices = listed(runtime, others);
	REQUIRE(devices.size() == 3);
	CHECK(devices[0].id == "sdl:Arduino LLC Arduino Leonardo#0");
	CHECK_FALSE(devices[0].openable);
	CHECK(devices[0].unavailable_reason == claims[0].reason);
	CHECK(devices[0].vendor_id == 0x2341); // Found by its joystick's name, which was not opened.
	CHECK(devices[1].id == "sdl:Xbox 360 Controller#0");
	CHECK(devices[1].openable); // evdev's entry claims nothing.
	CHECK(devices[2].id == "sdl:DualSense Wireless Controller#0");
	CHECK_FALSE(devices[2].openable);
	CHECK(devices[2].unavailable_reason.find("driven by the dualsense backend here") == 0);
	// Neither the stick (haptic or joystick) nor the DualSense was opened through SDL; the pad was.
	for (const ScriptedSdlCall &call : sdl.calls()) {
		const bool stick = call.haptic == 0 &&
				(call.kind == Kind::OPEN || call.kind == Kind::JOYSTICK_OPEN || call.kind == Kind::HAPTIC_FROM_JOYSTICK);
		CHECK_FALSE(stick);
		CHECK_FALSE((call.kind == Kind::JOYSTICK_OPEN && call.haptic == 2));
	}
	CHECK(calls_of(sdl.calls(), Kind::JOYSTICK_OPEN).size() == 1);
	CHECK(sdl.gain(0) == -1); // SDL never took the stick's gain.
	std::unique_ptr<HapticDevice> device;
	const Status opened = open_device(runtime, true, devices[0], false, device);
	CHECK(opened.code() == StatusCode::UNSUPPORTED);
	CHECK(std::strstr(opened.message(), "driven by the hid-pid backend") != nullptr);

	// hid-pid cannot open it (another program holds it, its reports are not usable): SDL's is offered.
	others[0].openable = false;
	devices = listed(runtime, others);
	REQUIRE(devices.size() == 3);
	CHECK(devices[0].openable);
	CHECK(devices[0].vendor_id == 0x2341); // Now through its joystick, opened.
	REQUIRE(open_device(runtime, true, devices[0], false, device).ok());
	device->close();
}

TEST_CASE("sdl joysticks: a joystick subsystem that does not start is a warning, and the haptics are still listed") {
	ScriptedSdl sdl({ scripted_sdl_stick() }, { scripted_sdl_xinput_pad() });
	SdlRuntime runtime(ScriptedSdl::api());
	sdl.fail_next(Kind::INIT, "Couldn't initialize DirectInput");
	std::vector<DeviceInfo> devices;
	std::vector<std::string> warnings;
	append_sdl_devices(runtime, driving(), devices, warnings);
	REQUIRE(warnings.size() == 1);
	CHECK(warnings[0] == "sdl: SDL's joystick subsystem did not start (no rumble pads listed): Couldn't initialize DirectInput");
	REQUIRE(devices.size() == 1);
	CHECK(devices[0].openable);
}
