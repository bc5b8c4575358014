#pragma once

// The part of SDL 3's C API the SDL backend calls, as a table of function pointers: the seam
// between the backend and SDL. Where the game's table comes from depends on the platform
// (docs/devices/sdl.md, "Where SDL comes from"):
//  - Linux: libSDL3.so.0 loaded at run time (sdl_library_posix.cpp: the extension does not link
//    SDL, so it loads where SDL is absent, and the exported game's copy is the engine's own);
//  - Windows: SDL linked in, static (sdl_library_windows.cpp: the DLL imports only Windows' own
//    DLLs, so there is no SDL3.dll to look for).
// Tests fill the table with a scripted SDL (dev_tools/sdl/scripted_sdl.h) that records every call.
// The types are SDL's own (its headers), so a pointer's type is the function's declared type and
// cannot drift from it. HAPTICS_SDL_FUNCTIONS is the one list of the functions: the table's
// members, the names the loader looks up and the addresses the linked build takes come from it.
//
// Every call through the table is made with SdlRuntime's mutex held (sdl_runtime.h): SDL's
// haptic functions keep global lists without locks of their own (SDL_haptic.c).

#include "core/base/status.h"

#include <SDL3/SDL_error.h>
#include <SDL3/SDL_haptic.h>
#include <SDL3/SDL_hints.h>
#include <SDL3/SDL_init.h>
#include <SDL3/SDL_joystick.h>
#include <SDL3/SDL_properties.h>
#include <SDL3/SDL_stdinc.h>
#include <SDL3/SDL_version.h>

#include <string>

namespace haptics::sdl {

// X(member): SDL_<member>. Every one exists since SDL 3.2.0. The haptic API and what the
// subsystems share, then the joystick API (Windows' rumble pads, and which joystick a haptic is).
#define HAPTICS_SDL_HAPTIC_FUNCTIONS(X) \
	X(GetVersion) \
	X(InitSubSystem) \
	X(QuitSubSystem) \
	X(GetError) \
	X(free) \
	X(GetHaptics) \
	X(GetHapticNameForID) \
	X(OpenHaptic) \
	X(CloseHaptic) \
	X(GetHapticFeatures) \
	X(GetNumHapticAxes) \
	X(GetMaxHapticEffects) \
	X(CreateHapticEffect) \
	X(UpdateHapticEffect) \
	X(RunHapticEffect) \
	X(StopHapticEffect) \
	X(DestroyHapticEffect) \
	X(SetHapticAutocenter) \
	X(InitHapticRumble) \
	X(PlayHapticRumble) \
	X(StopHapticRumble)
#define HAPTICS_SDL_JOYSTICK_FUNCTIONS(X) \
	X(SetHint) \
	X(GetJoysticks) \
	X(GetJoystickNameForID) \
	X(GetJoystickVendorForID) \
	X(GetJoystickProductForID) \
	X(OpenJoystick) \
	X(CloseJoystick) \
	X(JoystickConnected) \
	X(UpdateJoysticks) \
	X(SetJoystickEventsEnabled) \
	X(GetJoystickProperties) \
	X(GetBooleanProperty) \
	X(RumbleJoystick) \
	X(IsJoystickHaptic) \
	X(OpenHapticFromJoystick) \
	X(GetHapticID)
#define HAPTICS_SDL_FUNCTIONS(X) HAPTICS_SDL_HAPTIC_FUNCTIONS(X) HAPTICS_SDL_JOYSTICK_FUNCTIONS(X)

struct SdlApi {
#define HAPTICS_SDL_MEMBER(p_name) decltype(&SDL_##p_name) p_name = nullptr;
	HAPTICS_SDL_FUNCTIONS(HAPTICS_SDL_MEMBER)
#undef HAPTICS_SDL_MEMBER
};

// An effect's id: SDL 3.4 names it SDL_HapticEffectID, 3.2 (the Windows build's) returns an int.
using SdlEffectId = decltype(SDL_CreateHapticEffect(nullptr, nullptr));

// Which symbol of p_api is missing ("SDL_OpenHaptic"), or null when all are set.
const char *missing_sdl_function(const SdlApi &p_api);

// The oldest SDL whose API this backend calls.
inline constexpr int SDL_MIN_VERSION = SDL_VERSIONNUM(3, 2, 0);

struct SdlLibrary {
	void *handle = nullptr; // Null when linked in.
	SdlApi api;
	std::string path; // What loaded ("linked in" when SDL is part of the extension).
	int version = 0; // SDL_GetVersion(): major * 1000000 + minor * 1000 + patch.
};

// The process's SDL: linked in where it is (Windows), else loaded (load_sdl_library). The
// library stays for the process's life: SDL keeps threads and state of its own.
Status open_process_sdl(SdlLibrary &r_library);

// DEVICE_ERROR naming p_library.path and the first missing function, or an SDL older than
// SDL_MIN_VERSION; sets r_library.version.
Status check_sdl_library(SdlLibrary &r_library);

#ifndef _WIN32
// Where libSDL3 is looked for: the path in this variable, else the loader's search for
// SDL_LIBRARY_NAME (the exported game's runtime/lib/, where Debian's Godot template already
// needs it, or the system's ld.so.cache).
inline constexpr char SDL_LIBRARY_ENV[] = "HAPTICS_SDL3_LIBRARY";
inline constexpr char SDL_LIBRARY_NAME[] = "libSDL3.so.0";

// Loads p_path (empty: $HAPTICS_SDL3_LIBRARY, else SDL_LIBRARY_NAME) and resolves every
// function. NO_DEVICE "SDL 3 not found (...)" when no such library exists; DEVICE_ERROR naming
// the library and what failed when it is there but unusable (a missing function, too old).
Status load_sdl_library(const std::string &p_path, SdlLibrary &r_library);
#endif

} // namespace haptics::sdl
