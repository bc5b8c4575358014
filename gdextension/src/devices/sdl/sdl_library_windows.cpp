#include "devices/sdl/sdl_api.h"

// SDL linked in (sdl_api.h): tools/windows/build-deps.sh builds SDL 3 static from Debian's
// source package, so the DLL carries its own SDL and imports only Windows' own DLLs. Nothing is
// loaded: the table takes the functions' addresses. This copy of SDL is private to the
// extension (its symbols are not exported), so the engine's own SDL, if it has one, is another.

namespace haptics::sdl {

Status open_process_sdl(SdlLibrary &r_library) {
	SdlLibrary library;
	library.path = "SDL linked into the extension";
#define HAPTICS_SDL_LINK(p_name) library.api.p_name = &SDL_##p_name;
	HAPTICS_SDL_FUNCTIONS(HAPTICS_SDL_LINK)
#undef HAPTICS_SDL_LINK
	const Status usable = check_sdl_library(library);
	if (!usable) {
		return usable;
	}
	r_library = library;
	return Status::success();
}

} // namespace haptics::sdl
