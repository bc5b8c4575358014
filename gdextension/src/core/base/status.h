#pragma once

// The result of every fallible call of the core. Nothing in the core throws, because the
// binding calls it across the engine's C interface; a Status carries a code the binding can
// branch on and a message that names the offending parameter, e.g.
// "frame.contacts[2].normal: not finite (nan, 0, 1)". The message lives in a fixed buffer so
// that making or copying a Status never allocates.

#include <cstddef>
#include <cstdint>

// MinGW's GCC checks "printf" formats against Microsoft's C runtime, which lacks %zu; the
// Windows build formats with MinGW's C99 printf (__USE_MINGW_ANSI_STDIO, cmake/windows.cmake).
#ifdef __MINGW32__
#define HAPTICS_PRINTF gnu_printf
#else
#define HAPTICS_PRINTF printf
#endif

namespace haptics {

enum class StatusCode : int32_t {
	OK = 0,
	INVALID_ARGUMENT = 1, // Not finite, zero where a direction is needed, too many items.
	OUT_OF_RANGE = 2, // Finite but outside the documented range.
	INVALID_STATE = 3, // E.g. step() while the servo thread runs.
	NO_DEVICE = 4,
	DEVICE_ERROR = 5, // The device refused an operation (open, calibrate, ...).
	DEVICE_DISCONNECTED = 6,
	UNSUPPORTED = 7, // E.g. a hand target on a real device.
};

class Status {
public:
	static constexpr size_t MESSAGE_CAPACITY = 224;

	constexpr Status() = default;

	static Status success() { return Status(); }
	// printf-style; the message is truncated to MESSAGE_CAPACITY - 1 bytes.
	static Status error(StatusCode p_code, const char *p_format, ...) __attribute__((format(HAPTICS_PRINTF, 2, 3)));

	bool ok() const { return code_ == StatusCode::OK; }
	explicit operator bool() const { return ok(); }
	StatusCode code() const { return code_; }
	// Empty for success.
	const char *message() const { return message_; }

private:
	StatusCode code_ = StatusCode::OK;
	char message_[MESSAGE_CAPACITY] = {};
};

} // namespace haptics

// Returns from the enclosing function with the Status of `expression` when it is an error (the
// validators chain their checks with it).
#define HAPTICS_RETURN_IF_ERROR(expression) \
	do { \
		const Status status_ = (expression); \
		if (!status_) { \
			return status_; \
		} \
	} while (false)
