// DurableFile: crash-safe file writes for GDScript (study data). Paths are native file
// paths: pass ProjectSettings.globalize_path("user://...") from GDScript.
#pragma once

#include <string>

#include "binding/class_db.h"

namespace haptics::binding {

class DurableFile : public gd::ExtensionObject {
public:
	static void bind_methods(gd::ClassBinder<DurableFile> &r_binder);

	// Appends text and fsyncs before returning; false (and an error) on failure.
	bool append(const std::string &p_path, const std::string &p_text);
	// Writes a whole file atomically (temporary, fsync, rename). With replace false an
	// existing file is refused and kept.
	bool write(const std::string &p_path, const std::string &p_text, bool p_replace);
	bool make_dirs(const std::string &p_path);
	// 1: every line ends with '\n'; 0: the last record was cut short; -1: unreadable.
	int64_t check_complete(const std::string &p_path);
};

} // namespace haptics::binding
