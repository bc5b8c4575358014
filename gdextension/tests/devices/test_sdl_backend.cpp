// The SDL backend's listing and choice (devices/sdl/sdl_backend.h) over a scripted SDL: which
// haptics are offered and why not, that on Linux SDL is not even asked to open what the evdev
// backend drives, the keys that survive a rescan, and the table's one list of functions.
// Joysticks and the rule against the specialised backends: test_sdl_joystick.cpp.

#include "devices/sdl/sdl_api.h"
#include "devices/sdl/sdl_backend.h"
#include "scoped_variable.h"
#include "sdl_test_support.h"
#include "system/device_factory.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cstring>

using namespace haptics;
using namespace haptics::sdl;
using namespace haptics::sdl_test;

namespace {

std::vector<DeviceInfo> listed(SdlRuntime &r_runtime, bool p_drives) {
	std::vector<DeviceInfo> devices;
	std::vector<std::string> warnings;
	SdlListOptions options;
	options.read = p_drives;
	append_sdl_devices(r_runtime, options, devices, warnings);
	CHECK(warnings.empty());
	return devices;
}

size_t count(const std::vector<ScriptedSdlCall> &p_calls, Kind p_kind) {
	return calls_of(p_calls, p_kind).size();
}

} // namespace

TEST_CASE("sdl backend: where evdev drives SDL's haptics they are listed as such and SDL never opens them") {
	ScriptedSdl sdl({ scripted_sdl_stick(), scripted_sdl_pad() });
	SdlRuntime runtime(ScriptedSdl::api());
	const std::vector<DeviceInfo> devices = listed(runtime, false);
	REQUIRE(devices.size() == 2);
	for (const DeviceInfo &info : devices) {
		CHECK(info.backend == BACKEND_SDL);
		CHECK(info.driver == DRIVER_SDL);
		CHECK_FALSE(info.openable);
		CHECK(info.unavailable_reason.find("driven by the evdev backend here") != std::string::npos);
		CHECK(info.unavailable_reason.find("HAPTICS_SDL_ON_LINUX=1") != std::string::npos);
		CHECK_FALSE(probe(runtime, false, info).openable);
	}
	// Reading features would have opened them, and SDL's open sets the player's gain.
	CHECK(count(sdl.calls(), Kind::OPEN) == 0);
	CHECK(sdl.gain(0) == -1);
	std::unique_ptr<HapticDevice> device;
	const Status opened = open_device(runtime, false, devices[0], false, device);
	CHECK(opened.code() == StatusCode::UNSUPPORTED);
	CHECK(std::strstr(opened.message(), "driven by the evdev backend") != nullptr);
	CHECK(device == nullptr);
	CHECK(count(sdl.calls(), Kind::OPEN) == 0);
}

TEST_CASE("sdl backend: where SDL drives, each haptic says what it offers, and one with neither force nor rumble says so") {
	ScriptedHaptic bare = scripted_sdl_stick();
	bare.name = "Gain only";
	bare.features = SDL_HAPTIC_GAIN | SDL_HAPTIC_AUTOCENTER;
	ScriptedHaptic denied = scripted_sdl_pad();
	denied.name = "Denied";
	denied.open_error = "Haptic: Unable to open /dev/input/event4: Permission denied";
	ScriptedSdl sdl({ scripted_sdl_stick(), scripted_sdl_stick(), scripted_sdl_pad(), bare, denied });
	SdlRuntime runtime(ScriptedSdl::api());
	const std::vector<DeviceInfo> devices = listed(runtime, true);
	REQUIRE(devices.size() == 5);
	CHECK(devices[0].id == "sdl:Arduino LLC Arduino Leonardo#0");
	CHECK(devices[1].id == "sdl:Arduino LLC Arduino Leonardo#1"); // Same name: ranked.
	CHECK(devices[1].path == "Arduino LLC Arduino Leonardo#1");
	CHECK(devices[0].product == "Arduino LLC Arduino Leonardo");
	CHECK(devices[0].openable);
	CHECK(devices[2].openable);
	CHECK_FALSE(devices[3].openable);
	CHECK(devices[3].unavailable_reason ==
			"SDL offers neither constant force nor rumble on this device (gain autocenter, 2 axes, 16 effects)");
	CHECK_FALSE(devices[4].openable);
	CHECK(devices[4].unavailable_reason == "SDL cannot open it: Haptic: Unable to open /dev/input/event4: Permission denied");
	for (size_t i = 0; i < devices.size(); ++i) {
		const DeviceAvailability availability = probe(runtime, true, devices[i]);
		CHECK(availability.handled);
		CHECK(availability.openable == devices[i].openable);
		CHECK(availability.reason == devices[i].unavailable_reason);
	}
	// Every haptic opened to read its features was closed again.
	for (size_t i = 0; i < 4; ++i) {
		CHECK(sdl.open_references(i) == 0);
	}
	DeviceInfo other;
	other.backend = BACKEND_EVDEV;
	CHECK_FALSE(probe(runtime, true, other).handled);
}

TEST_CASE("sdl backend: a listing rescans while nothing is open, and keeps SDL's list while a device is") {
	ScriptedSdl sdl({ scripted_sdl_stick(), scripted_sdl_pad() });
	SdlRuntime runtime(ScriptedSdl::api());
	std::vector<DeviceInfo> devices = listed(runtime, true);
	REQUIRE(devices.size() == 2);
	sdl.set_plugged(1, false);
	devices = listed(runtime, true);
	REQUIRE(devices.size() == 1); // Quit and init again: a fresh scan.
	CHECK(devices[0].id == "sdl:Arduino LLC Arduino Leonardo#0");
	sdl.set_plugged(1, true);

	std::unique_ptr<HapticDevice> device;
	REQUIRE(open_device(runtime, true, devices[0], false, device).ok());
	sdl.clear_calls();
	devices = listed(runtime, true);
	CHECK(devices.size() == 1); // Not rescanned: the pad plugged meanwhile shows once the stick is closed.
	CHECK(count(sdl.calls(), Kind::QUIT) == 0);
	CHECK(sdl.open_references(0) == 1);
	device->close();
	devices = listed(runtime, true);
	CHECK(devices.size() == 2);
	CHECK(sdl.subsystem_count() == 1);
}

TEST_CASE("sdl backend: SDL's haptics are driven by SDL on Linux only when HAPTICS_SDL_ON_LINUX is 1") {
#ifdef __linux__
	{
		const testing::ScopedVariable unset(SDL_ON_LINUX_ENV, nullptr);
		CHECK_FALSE(sdl_drives_here());
	}
	{
		const testing::ScopedVariable zero(SDL_ON_LINUX_ENV, "0");
		CHECK_FALSE(sdl_drives_here());
	}
	const testing::ScopedVariable one(SDL_ON_LINUX_ENV, "1");
	CHECK(sdl_drives_here());
#else
	CHECK(sdl_drives_here());
#endif
}

TEST_CASE("sdl api: the scripted table is complete, and a missing function is named") {
	SdlApi api = ScriptedSdl::api();
	CHECK(missing_sdl_function(api) == nullptr);
	api.PlayHapticRumble = nullptr;
	CHECK(std::strcmp(missing_sdl_function(api), "SDL_PlayHapticRumble") == 0);
	api = ScriptedSdl::api();
	api.RumbleJoystick = nullptr;
	CHECK(std::strcmp(missing_sdl_function(api), "SDL_RumbleJoystick") == 0);
}

TEST_CASE("sdl backend: the device factory routes sdl entries to the SDL row, which refuses cleanly when it cannot open") {
	const testing::ScopedVariable unset(SDL_ON_LINUX_ENV, nullptr);
	std::vector<DeviceInfo> devices(1);
	devices[0].id = "sdl:Nothing here#0";
	devices[0].backend = BACKEND_SDL;
	devices[0].path = "Nothing here#0";
	probe_devices(devices);
	CHECK(devices[0].driver == DRIVER_SDL);
	CHECK_FALSE(devices[0].openable);
	// Without libSDL3 (this machine's Debian 12 has none): "SDL 3 not found"; with one: SDL's
	// haptics are the evdev backend's here, or this one is not listed.
	CHECK_FALSE(devices[0].unavailable_reason.empty());
	CHECK(devices[0].unavailable_reason.find("no force-feedback driver") == std::string::npos);
	std::unique_ptr<HapticDevice> device;
	const Status opened = open_listed_device(devices[0], DeviceOpenOptions{}, device);
	CHECK_FALSE(opened.ok());
	CHECK(device == nullptr);
}
