#pragma once

// The system's loader for a library the player installed or the game's runtime carries (the
// OpenHaptics runtime, libSDL3), one implementation per platform (dynamic_library_posix.cpp:
// dlopen; dynamic_library_windows.cpp: LoadLibrary). Each caller's search rule and messages
// are its own (hd_runtime.h, sdl_api.h).

#include <cstddef>

namespace haptics {

// Loads p_path (a path, or a bare name the loader searches for) with every dependency bound
// now, so a broken library fails here and not in the servo, and its symbols kept local. On failure returns null, sets
// r_missing when no such file was found (rather than found but unloadable), and writes the
// loader's reason to r_error.
void *open_dynamic_library(const char *p_path, bool &r_missing, char *r_error, size_t p_capacity);
// The address of p_name, or null.
void *dynamic_library_symbol(void *p_handle, const char *p_name);
void close_dynamic_library(void *p_handle);
// Keeps the library named p_name, when this process has it loaded, loaded until the process
// ends whoever frees it; nothing when it is not loaded, or where there is no such thing (POSIX).
void pin_loaded_library(const char *p_name);

} // namespace haptics
