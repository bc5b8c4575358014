#include "devices/dynamic_library.h"

#include <cstdio>
#include <cstring>
#include <dlfcn.h>

namespace haptics {

void *open_dynamic_library(const char *p_path, bool &r_missing, char *r_error, size_t p_capacity) {
	// RTLD_NOW: a library with unresolvable dependencies fails here, not in the servo.
	// RTLD_LOCAL: its symbols stay out of the global namespace (no clash with another copy).
	void *handle = dlopen(p_path, RTLD_NOW | RTLD_LOCAL);
	if (handle != nullptr) {
		return handle;
	}
	const char *error = dlerror();
	if (error == nullptr) {
		error = "dlopen failed";
	}
	// glibc says "<name>: cannot open shared object file" when the file itself is missing;
	// anything else (a missing dependency, a bad ELF) means it is there but broken.
	const size_t length = std::strlen(p_path);
	r_missing = std::strncmp(error, p_path, length) == 0 &&
			std::strncmp(error + length, ": cannot open shared object file", 32) == 0;
	std::snprintf(r_error, p_capacity, "%s", error);
	return nullptr;
}

// POSIX guarantees a dlsym result converts to a function pointer.
void *dynamic_library_symbol(void *p_handle, const char *p_name) {
	return dlsym(p_handle, p_name);
}

void close_dynamic_library(void *p_handle) {
	dlclose(p_handle);
}

void pin_loaded_library(const char *) {}

} // namespace haptics
