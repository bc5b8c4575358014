#include "core/status.h"

#include <cstdarg>
#include <cstdio>

namespace haptics {

const char *status_code_name(StatusCode p_code) {
	switch (p_code) {
		case StatusCode::OK:
			return "ok";
		case StatusCode::INVALID_ARGUMENT:
			return "invalid argument";
		case StatusCode::OUT_OF_RANGE:
			return "out of range";
		case StatusCode::INVALID_STATE:
			return "invalid state";
		case StatusCode::NO_DEVICE:
			return "no device";
		case StatusCode::DEVICE_ERROR:
			return "device error";
		case StatusCode::DEVICE_DISCONNECTED:
			return "device disconnected";
		case StatusCode::UNSUPPORTED:
			return "unsupported";
	}
	return "unknown";
}

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
