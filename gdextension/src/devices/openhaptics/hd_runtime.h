#pragma once

// Where the user's OpenHaptics runtime is, the same rule on every platform
// (docs/devices/openhaptics.md, "Finding the library"): the
// path in the environment variable HAPTICS_OPENHAPTICS_LIBRARY, then the names its
// installers create, found by the system's loader (dynamic_library.h):
//   Linux    "libHD.so", "libHD.so.3.4", "libHD.so.3.0" (ld.so.cache, LD_LIBRARY_PATH)
//   Windows  "hd.dll" (the installer puts OpenHaptics' bin folder on PATH; LoadLibrary's
//            search order: the game's folder, the system folders, PATH)

#include "core/base/status.h"
#include "devices/openhaptics/hd_api.h"

#include <string>

namespace haptics::openhaptics {

inline constexpr char HD_LIBRARY_ENV[] = "HAPTICS_OPENHAPTICS_LIBRARY";
#ifdef _WIN32
#define HAPTICS_HD_LIBRARY "hd.dll"
inline constexpr const char *HD_LIBRARY_NAMES[] = { HAPTICS_HD_LIBRARY };
#else
#define HAPTICS_HD_LIBRARY "libHD.so"
inline constexpr const char *HD_LIBRARY_NAMES[] = { HAPTICS_HD_LIBRARY, "libHD.so.3.4", "libHD.so.3.0" };
#endif

// The reason when nothing is installed, worded for the player.
inline constexpr char HD_RUNTIME_NOT_FOUND[] = "OpenHaptics runtime not found (" HAPTICS_HD_LIBRARY
											   "): install 3D Systems' OpenHaptics and Touch driver, or set "
											   "HAPTICS_OPENHAPTICS_LIBRARY";

// Loads p_explicit_path when it is non-empty (tests, a DeviceInfo's path), else searches.
// When no candidate exists: NO_DEVICE with HD_RUNTIME_NOT_FOUND (plus why the environment
// variable's path failed, when it is set). When a candidate exists but is broken (missing
// dependency, missing function): that candidate's error, which says what to fix.
Status load_hd_runtime(const char *p_explicit_path, HdLibrary &r_library);

struct HdRuntimeLocation {
	bool loadable = false;
	std::string path; // What loaded, e.g. "libHD.so" or the variable's path.
	std::string reason; // Why not, when !loadable.
};

// Loads and unloads the runtime to tell whether it would open (every symbol resolved).
// Game thread; dlopen runs the runtime's initialisers, so call it from a menu, not per frame.
HdRuntimeLocation locate_hd_runtime(const char *p_explicit_path = nullptr);

} // namespace haptics::openhaptics
