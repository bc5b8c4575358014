// Loading libSDL3 at run time (devices/sdl/sdl_library_posix.cpp), as Linux does: what a
// missing or foreign library says. Windows links SDL in instead (test_sdl_library_windows.cpp).

#include "devices/sdl/sdl_api.h"
#include "scoped_variable.h"

#include <doctest/doctest.h>

#include <cstring>

using namespace haptics;
using namespace haptics::sdl;

TEST_CASE("sdl library: a missing libSDL3 is 'not found', a library without SDL's functions names the first missing") {
	SdlLibrary library;
	Status loaded = load_sdl_library("/nonexistent/libSDL3.so.0", library);
	CHECK(loaded.code() == StatusCode::NO_DEVICE);
	CHECK(std::strstr(loaded.message(), "SDL 3 not found (/nonexistent/libSDL3.so.0)") != nullptr);
	loaded = load_sdl_library(HAPTICS_FAKE_HD_PATH, library); // A real library, but not SDL.
	CHECK(loaded.code() == StatusCode::DEVICE_ERROR);
	CHECK(std::strstr(loaded.message(), "is not SDL 3 or too old: it has no SDL_GetVersion") != nullptr);
	CHECK(library.handle == nullptr);
	{
		const testing::ScopedVariable path(SDL_LIBRARY_ENV, "/nonexistent/elsewhere.so");
		CHECK(std::strstr(load_sdl_library("", library).message(), "/nonexistent/elsewhere.so") != nullptr);
	}
}
