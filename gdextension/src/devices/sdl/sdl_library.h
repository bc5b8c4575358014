#pragma once

// The system's loader for libSDL3, one implementation per platform (sdl_library_posix.cpp:
// dlopen; Windows: LoadLibrary, with the Windows half of the backend).

#include <cstddef>

namespace haptics::sdl {

// Loads p_path with every dependency bound now and its symbols kept local. On failure returns
// null, sets r_missing when no such file was found (rather than found but unloadable), and
// writes the loader's reason to r_error.
void *open_sdl_library(const char *p_path, bool &r_missing, char *r_error, size_t p_capacity);
// The address of p_name, or null.
void *sdl_library_symbol(void *p_handle, const char *p_name);

} // namespace haptics::sdl
