#include "devices/sdl/sdl_api.h"

#include "devices/dynamic_library.h"

#include <cstdlib>
#include <type_traits>

namespace haptics::sdl {

namespace {

// Each member of SdlApi with its C name, in the order of the struct.
template <typename Visitor>
void visit_functions(SdlApi &r_api, Visitor p_visit) {
	p_visit("SDL_GetVersion", r_api.GetVersion);
	p_visit("SDL_InitSubSystem", r_api.InitSubSystem);
	p_visit("SDL_QuitSubSystem", r_api.QuitSubSystem);
	p_visit("SDL_GetError", r_api.GetError);
	p_visit("SDL_free", r_api.Free);
	p_visit("SDL_GetHaptics", r_api.GetHaptics);
	p_visit("SDL_GetHapticNameForID", r_api.GetHapticNameForID);
	p_visit("SDL_OpenHaptic", r_api.OpenHaptic);
	p_visit("SDL_CloseHaptic", r_api.CloseHaptic);
	p_visit("SDL_GetHapticFeatures", r_api.GetHapticFeatures);
	p_visit("SDL_GetNumHapticAxes", r_api.GetNumHapticAxes);
	p_visit("SDL_GetMaxHapticEffects", r_api.GetMaxHapticEffects);
	p_visit("SDL_CreateHapticEffect", r_api.CreateHapticEffect);
	p_visit("SDL_UpdateHapticEffect", r_api.UpdateHapticEffect);
	p_visit("SDL_RunHapticEffect", r_api.RunHapticEffect);
	p_visit("SDL_StopHapticEffect", r_api.StopHapticEffect);
	p_visit("SDL_DestroyHapticEffect", r_api.DestroyHapticEffect);
	p_visit("SDL_SetHapticAutocenter", r_api.SetHapticAutocenter);
	p_visit("SDL_InitHapticRumble", r_api.InitHapticRumble);
	p_visit("SDL_PlayHapticRumble", r_api.PlayHapticRumble);
	p_visit("SDL_StopHapticRumble", r_api.StopHapticRumble);
}

} // namespace

const char *missing_sdl_function(const SdlApi &p_api) {
	SdlApi copy = p_api;
	const char *missing = nullptr;
	visit_functions(copy, [&](const char *p_name, auto &p_function) {
		if (missing == nullptr && p_function == nullptr) {
			missing = p_name;
		}
	});
	return missing;
}

Status load_sdl_library(const std::string &p_path, SdlLibrary &r_library) {
	std::string path = p_path;
	if (path.empty()) {
		const char *env = std::getenv(SDL_LIBRARY_ENV);
		path = env != nullptr && env[0] != '\0' ? env : SDL_LIBRARY_NAME;
	}
	char error[512] = {};
	bool missing = false;
	// In the exported game Godot has already loaded the same libSDL3.so.0: this is that copy.
	void *handle = open_dynamic_library(path.c_str(), missing, error, sizeof(error));
	if (handle == nullptr) {
		return Status::error(missing ? StatusCode::NO_DEVICE : StatusCode::DEVICE_ERROR, "SDL 3 %s (%s): %s",
				missing ? "not found" : "cannot be loaded", path.c_str(), error);
	}
	SdlLibrary library;
	library.handle = handle;
	library.path = path;
	visit_functions(library.api, [&](const char *p_name, auto &r_function) {
		// POSIX and Windows both guarantee a symbol's address converts to a function pointer.
		r_function = reinterpret_cast<std::remove_reference_t<decltype(r_function)>>(dynamic_library_symbol(handle, p_name));
	});
	if (const char *absent = missing_sdl_function(library.api)) {
		return Status::error(StatusCode::DEVICE_ERROR, "%s is not SDL 3 or too old: it has no %s", path.c_str(), absent);
	}
	library.version = library.api.GetVersion();
	if (library.version < SDL_MIN_VERSION) {
		return Status::error(StatusCode::DEVICE_ERROR, "%s is SDL %d.%d.%d; the haptic backend needs 3.2.0 or newer",
				path.c_str(), SDL_VERSIONNUM_MAJOR(library.version), SDL_VERSIONNUM_MINOR(library.version),
				SDL_VERSIONNUM_MICRO(library.version));
	}
	r_library = library;
	return Status::success();
}

} // namespace haptics::sdl
