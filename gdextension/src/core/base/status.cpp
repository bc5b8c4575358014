#include "core/base/status.h"

#include <cstdarg>
#include <cstdio>

namespace haptics {

Status Status::error(StatusCode p_code, const char *p_format, ...) {
	Status status;
	status.code_ = p_code;
	va_list args;
	va_start(args, p_format);
	std::vsnprintf(status.message_, MESSAGE_CAPACITY, p_format, args);
	va_end(args);
	return status;
}

} // namespace haptics
