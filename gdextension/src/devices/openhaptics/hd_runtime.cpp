#include "devices/openhaptics/hd_runtime.h"

#include <cstdlib>

namespace haptics::openhaptics {

Status load_hd_runtime(const char *p_explicit_path, HdLibrary &r_library) {
	if (p_explicit_path != nullptr && p_explicit_path[0] != '\0') {
		const Status loaded = r_library.load(p_explicit_path);
		if (!loaded && loaded.code() == StatusCode::NO_DEVICE) {
			return Status::error(StatusCode::NO_DEVICE, "%s [%s]", HD_RUNTIME_NOT_FOUND, loaded.message());
		}
		return loaded;
	}

	const char *variable = std::getenv(HD_LIBRARY_ENV);
	Status variable_error;
	if (variable != nullptr && variable[0] != '\0') {
		variable_error = r_library.load(variable);
		if (variable_error) {
			return variable_error;
		}
		if (variable_error.code() != StatusCode::NO_DEVICE) {
			// The user pointed at a file that is there but broken: say that, not "not found".
			return variable_error;
		}
	}
	for (const char *name : HD_LIBRARY_NAMES) {
		const Status loaded = r_library.load(name);
		if (loaded) {
			return loaded;
		}
		if (loaded.code() != StatusCode::NO_DEVICE) {
			return loaded;
		}
	}
	if (!variable_error) {
		return Status::error(StatusCode::NO_DEVICE, "%s [%s=%s: no such file]", HD_RUNTIME_NOT_FOUND, HD_LIBRARY_ENV,
				variable);
	}
	return Status::error(StatusCode::NO_DEVICE, "%s", HD_RUNTIME_NOT_FOUND);
}

HdRuntimeLocation locate_hd_runtime(const char *p_explicit_path) {
	HdRuntimeLocation location;
	HdLibrary library;
	const Status loaded = load_hd_runtime(p_explicit_path, library);
	location.loadable = loaded.ok();
	if (location.loadable) {
		location.path = library.path();
	} else {
		location.reason = loaded.message();
	}
	return location;
}

} // namespace haptics::openhaptics
