#pragma once

// The system's loader for the user's HD runtime, one implementation per platform
// (hd_library_posix.cpp: dlopen; hd_library_windows.cpp: LoadLibrary). The search rule and
// the messages around it are hd_runtime.h's, the same everywhere.

#include <cstddef>

namespace haptics::openhaptics {

// Loads p_path (a path, or a bare name the loader searches for) with every dependency bound
// now, so a broken runtime fails here and not in the servo. On failure returns null, sets
// r_missing when no such file was found (rather than found but unloadable), and writes the
// loader's reason to r_error.
void *open_library(const char *p_path, bool &r_missing, char *r_error, size_t p_capacity);
// The address of p_name, or null.
void *library_symbol(void *p_handle, const char *p_name);
void close_library(void *p_handle);

} // namespace haptics::openhaptics
