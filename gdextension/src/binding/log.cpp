#include "binding/log.h"

#include "binding/interface.h"

namespace gd {

void print_error(const std::string &p_message, const char *p_function, const char *p_file,
		int p_line) {
	api.print_error_with_message("haptics", p_message.c_str(), p_function, p_file, p_line, 1);
}

void print_warning(const std::string &p_message, const char *p_function, const char *p_file,
		int p_line) {
	api.print_warning_with_message("haptics", p_message.c_str(), p_function, p_file, p_line, 1);
}

} // namespace gd
