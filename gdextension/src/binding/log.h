// Errors and warnings through the engine's own printer, so they show in the editor's
// debugger and in headless logs with the usual "ERROR:" prefix. Main thread only: the
// servo thread never logs.
#pragma once

#include <string>

namespace gd {

void print_error(const std::string &p_message, const char *p_function, const char *p_file,
		int p_line);
void print_warning(const std::string &p_message, const char *p_function, const char *p_file,
		int p_line);

} // namespace gd

#define HAPTICS_ERROR(message) ::gd::print_error((message), __func__, __FILE__, __LINE__)
#define HAPTICS_WARNING(message) ::gd::print_warning((message), __func__, __FILE__, __LINE__)
