#pragma once

// The part of SDL 3's C API the SDL backend calls, as a table of function pointers: the seam
// between the backend and SDL. The game's table is filled from libSDL3 loaded at run time
// (load_sdl_library below: the extension does not link SDL, so it loads where SDL is absent);
// tests fill it with a scripted SDL (dev_tools/sdl/scripted_sdl.h) that records every effect.
// The types are SDL's own (its headers, Debian testing's libsdl3-dev: tools/provision-sdl3.sh),
// so a pointer's type is the function's declared type and cannot drift from it.
//
// Every call through the table is made with SdlRuntime's mutex held (sdl_runtime.h): SDL's
// haptic functions keep global lists without locks of their own (SDL_haptic.c).

#include "core/base/status.h"

#include <SDL3/SDL_error.h>
#include <SDL3/SDL_haptic.h>
#include <SDL3/SDL_init.h>
#include <SDL3/SDL_stdinc.h>
#include <SDL3/SDL_version.h>

#include <cstddef>
#include <string>

namespace haptics::sdl {

struct SdlApi {
	decltype(&SDL_GetVersion) GetVersion = nullptr;
	decltype(&SDL_InitSubSystem) InitSubSystem = nullptr;
	decltype(&SDL_QuitSubSystem) QuitSubSystem = nullptr;
	decltype(&SDL_GetError) GetError = nullptr;
	decltype(&SDL_free) Free = nullptr;
	decltype(&SDL_GetHaptics) GetHaptics = nullptr;
	decltype(&SDL_GetHapticNameForID) GetHapticNameForID = nullptr;
	decltype(&SDL_OpenHaptic) OpenHaptic = nullptr;
	decltype(&SDL_CloseHaptic) CloseHaptic = nullptr;
	decltype(&SDL_GetHapticFeatures) GetHapticFeatures = nullptr;
	decltype(&SDL_GetNumHapticAxes) GetNumHapticAxes = nullptr;
	decltype(&SDL_GetMaxHapticEffects) GetMaxHapticEffects = nullptr;
	decltype(&SDL_CreateHapticEffect) CreateHapticEffect = nullptr;
	decltype(&SDL_UpdateHapticEffect) UpdateHapticEffect = nullptr;
	decltype(&SDL_RunHapticEffect) RunHapticEffect = nullptr;
	decltype(&SDL_StopHapticEffect) StopHapticEffect = nullptr;
	decltype(&SDL_DestroyHapticEffect) DestroyHapticEffect = nullptr;
	decltype(&SDL_SetHapticAutocenter) SetHapticAutocenter = nullptr;
	decltype(&SDL_InitHapticRumble) InitHapticRumble = nullptr;
	decltype(&SDL_PlayHapticRumble) PlayHapticRumble = nullptr;
	decltype(&SDL_StopHapticRumble) StopHapticRumble = nullptr;
};

// Which symbol of p_api is missing ("SDL_OpenHaptic"), or null when all are set.
const char *missing_sdl_function(const SdlApi &p_api);

// Where libSDL3 is looked for: the path in this variable, else the loader's search for
// SDL_LIBRARY_NAME (on Linux the exported game's runtime/lib/, where Debian's Godot template
// already needs it, or the system's ld.so.cache).
inline constexpr char SDL_LIBRARY_ENV[] = "HAPTICS_SDL3_LIBRARY";
#ifdef _WIN32
inline constexpr char SDL_LIBRARY_NAME[] = "SDL3.dll";
#else
inline constexpr char SDL_LIBRARY_NAME[] = "libSDL3.so.0";
#endif
// The oldest SDL whose haptic API this backend calls (every function above exists since 3.2.0).
inline constexpr int SDL_MIN_VERSION = SDL_VERSIONNUM(3, 2, 0);

struct SdlLibrary {
	void *handle = nullptr;
	SdlApi api;
	std::string path; // What loaded.
	int version = 0; // SDL_GetVersion(): major * 1000000 + minor * 1000 + patch.
};

// Loads p_path (empty: $HAPTICS_SDL3_LIBRARY, else SDL_LIBRARY_NAME) and resolves every
// function. NO_DEVICE "SDL 3 not found (...)" when no such library exists; DEVICE_ERROR naming
// the library and what failed when it is there but unusable (a missing function, too old).
// The handle stays loaded for the process's life: SDL keeps threads and state of its own.
Status load_sdl_library(const std::string &p_path, SdlLibrary &r_library);

} // namespace haptics::sdl
