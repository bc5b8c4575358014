#include "devices/dynamic_library.h"
#include "devices/sdl/sdl_api.h"

#include <cstdlib>
#include <type_traits>

// SDL loaded at run time (sdl_api.h): the extension does not link libSDL3, so it loads where
// SDL is missing, and in the exported game it takes the copy Debian's Godot template loaded.

namespace haptics::sdl {

Status load_sdl_library(const std::string &p_path, SdlLibrary &r_library) {
	std::string path = p_path;
	if (path.empty()) {
		const char *env = std::getenv(SDL_LIBRARY_ENV);
		path = env != nullptr && env[0] != '\0' ? env : SDL_LIBRARY_NAME;
	}
	char error[512] = {};
	bool missing = false;
	void *handle = open_dynamic_library(path.c_str(), missing, error, sizeof(error));
	if (handle == nullptr) {
		return Status::error(missing ? StatusCode::NO_DEVICE : StatusCode::DEVICE_ERROR, "SDL 3 %s (%s): %s",
				missing ? "not found" : "cannot be loaded", path.c_str(), error);
	}
	SdlLibrary library;
	library.handle = handle;
	library.path = path;
	// POSIX guarantees a symbol's address converts to a function pointer.
#define HAPTICS_SDL_RESOLVE(p_name) \
	library.api.p_name = reinterpret_cast<std::remove_reference_t<decltype(library.api.p_name)>>( \
			dynamic_library_symbol(handle, "SDL_" #p_name));
	HAPTICS_SDL_FUNCTIONS(HAPTICS_SDL_RESOLVE)
#undef HAPTICS_SDL_RESOLVE
	const Status usable = check_sdl_library(library);
	if (!usable) {
		return usable; // The handle stays loaded: unloading a library SDL may share is not worth the risk.
	}
	r_library = library;
	return Status::success();
}

Status open_process_sdl(SdlLibrary &r_library) {
	return load_sdl_library("", r_library);
}

} // namespace haptics::sdl
