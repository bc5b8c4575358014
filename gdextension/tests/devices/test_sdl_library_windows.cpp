// SDL linked into the Windows extension (devices/sdl/sdl_library_windows.cpp), run for real: under
// Wine in tools/windows/test.sh, which prints the "sdl under windows:" messages below as what
// Wine offers SDL (docs/devices/sdl.md, "Testing"). Linux loads SDL instead
// (test_sdl_library_linux.cpp).

#include "devices/sdl/sdl_backend.h"

#include <SDL3/SDL_hidapi.h>
#include <doctest/doctest.h>

#include <string>

using namespace haptics;
using namespace haptics::sdl;

TEST_CASE("sdl library: on Windows SDL is linked in, complete, and 3.2 or newer") {
	SdlLibrary library;
	REQUIRE(open_process_sdl(library).ok());
	CHECK(library.handle == nullptr); // Nothing loaded.
	CHECK(library.path == "SDL linked into the extension");
	CHECK(missing_sdl_function(library.api) == nullptr);
	CHECK(library.version >= SDL_MIN_VERSION);
	CHECK(library.version == SDL_VERSION); // The headers we compiled against are the SDL we link.
	CHECK(sdl_drives_here());
	CHECK(sdl_lists_joysticks_here());
}

TEST_CASE("sdl under windows: the haptic and joystick subsystems start, and the listing says why each entry cannot be used") {
	SdlLibrary library;
	REQUIRE(open_process_sdl(library).ok());
	std::vector<DeviceInfo> devices;
	std::vector<std::string> warnings;
	size_t haptics = 0;
	size_t joysticks = 0;
	{
		SdlRuntime runtime(library.api);
		SdlListOptions options;
		options.read = true;
		options.joysticks = true;
		append_sdl_devices(runtime, options, devices, warnings);
		CHECK(warnings.empty()); // Both subsystems started.
		for (const DeviceInfo &device : devices) {
			SdlHapticEntry entry;
			REQUIRE(runtime.entry(device.path, entry));
			(entry.kind == SdlEntryKind::HAPTIC ? haptics : joysticks) += 1;
			CHECK(device.backend == BACKEND_SDL);
			CHECK(device.openable == device.unavailable_reason.empty());
			MESSAGE("sdl under windows: ", device.id, ": ", device.openable ? "openable" : device.unavailable_reason);
		}
		// A second listing restarts both subsystems (nothing is open) and finds the same.
		std::vector<DeviceInfo> again;
		append_sdl_devices(runtime, options, again, warnings);
		CHECK(again.size() == devices.size());
		CHECK(runtime.open_count() == 0);
	} // Quits the subsystems.
	for (const std::string &warning : warnings) {
		MESSAGE("sdl under windows: warning: ", warning);
	}
	// SDL's own hidapi, behind its HIDAPI pad drivers (SDL drops those when it cannot start).
	const int hid = SDL_hid_init();
	MESSAGE("sdl under windows: SDL's HIDAPI (its PlayStation, Switch and Xbox-over-HID pad drivers) ",
			hid == 0 ? std::string("started") : std::string("did not start: ") + SDL_GetError());
	if (hid == 0) {
		SDL_hid_exit();
	}
	MESSAGE("sdl under windows: SDL ", SDL_VERSIONNUM_MAJOR(library.version), ".", SDL_VERSIONNUM_MINOR(library.version),
			".", SDL_VERSIONNUM_MICRO(library.version), " linked in; haptic and joystick subsystems started; ", haptics,
			" haptics and ", joysticks, " joysticks without a haptic listed");
}
