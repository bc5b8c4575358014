#pragma once

// What the devices made for a real kernel (uhid, uinput, USB gadgets) share: a failed system
// call as a Status, and how long their threads' polls wait before they look at their wake
// pipe again (shutdown latency only).

#include "core/base/status.h"

#include <cerrno>
#include <cstring>
#include <string>

namespace haptics {

inline constexpr int KERNEL_DEVICE_POLL_MS = 50;

// "<p_what> <p_object>: <strerror(errno)>", DEVICE_ERROR.
inline Status errno_status(const char *p_what, const std::string &p_object = "") {
	const char *error = std::strerror(errno);
	return Status::error(StatusCode::DEVICE_ERROR, "%s%s%s: %s", p_what, p_object.empty() ? "" : " ", p_object.c_str(), error);
}

} // namespace haptics
