#include "devices/sdl/sdl_api.h"

namespace haptics::sdl {

const char *missing_sdl_function(const SdlApi &p_api) {
#define HAPTICS_SDL_CHECK(p_name) \
	if (p_api.p_name == nullptr) { \
		return "SDL_" #p_name; \
	}
	HAPTICS_SDL_FUNCTIONS(HAPTICS_SDL_CHECK)
#undef HAPTICS_SDL_CHECK
	return nullptr;
}

Status check_sdl_library(SdlLibrary &r_library) {
	if (const char *absent = missing_sdl_function(r_library.api)) {
		return Status::error(StatusCode::DEVICE_ERROR, "%s is not SDL 3 or too old: it has no %s", r_library.path.c_str(),
				absent);
	}
	r_library.version = r_library.api.GetVersion();
	if (r_library.version < SDL_MIN_VERSION) {
		return Status::error(StatusCode::DEVICE_ERROR, "%s is SDL %d.%d.%d; the haptic backend needs 3.2.0 or newer",
				r_library.path.c_str(), SDL_VERSIONNUM_MAJOR(r_library.version), SDL_VERSIONNUM_MINOR(r_library.version),
				SDL_VERSIONNUM_MICRO(r_library.version));
	}
	return Status::success();
}

} // namespace haptics::sdl
