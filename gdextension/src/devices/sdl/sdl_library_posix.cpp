#include "devices/sdl/sdl_library.h"

#include <cstdio>
#include <cstring>
#include <dlfcn.h>

namespace haptics::sdl {

void *open_sdl_library(const char *p_path, bool &r_missing, char *r_error, size_t p_capacity) {
	// RTLD_NOW: an SDL whose dependencies do not resolve fails here, not on the I/O thread.
	// RTLD_LOCAL: its symbols stay out of the global namespace. In the exported game Godot has
	// already loaded the same libSDL3.so.0, and dlopen hands back that very copy.
	void *handle = dlopen(p_path, RTLD_NOW | RTLD_LOCAL);
	if (handle != nullptr) {
		return handle;
	}
	const char *error = dlerror();
	if (error == nullptr) {
		error = "dlopen failed";
	}
	// glibc: "<name>: cannot open shared object file" when the file itself is missing.
	const size_t length = std::strlen(p_path);
	r_missing = std::strncmp(error, p_path, length) == 0 &&
			std::strncmp(error + length, ": cannot open shared object file", 32) == 0;
	std::snprintf(r_error, p_capacity, "%s", error);
	return nullptr;
}

void *sdl_library_symbol(void *p_handle, const char *p_name) {
	return dlsym(p_handle, p_name);
}

} // namespace haptics::sdl
