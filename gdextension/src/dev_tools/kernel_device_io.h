#pragma once

// What the devices made for a real kernel (uhid, uinput, USB gadgets) share: a failed system
// call as a Status, and their threads' wait for the kernel or their wake pipe (how long it
// waits bounds only the shutdown latency).

#include "core/base/status.h"

#include <poll.h>

#include <cerrno>
#include <cstring>
#include <string>

namespace haptics {

inline constexpr int KERNEL_DEVICE_POLL_MS = 50;

enum class KernelDeviceWait {
	READABLE, // p_fd has something to read.
	IDLE, // Nothing yet: wait again.
	STOP, // The wake pipe was written, or poll failed: the thread ends.
};

// One wait of a kernel-facing device's thread: for p_fd to be readable or p_wake_fd (the read
// end of its wake pipe) to be written, at most KERNEL_DEVICE_POLL_MS.
inline KernelDeviceWait wait_kernel_device(int p_fd, int p_wake_fd) {
	pollfd fds[2] = { { p_fd, POLLIN, 0 }, { p_wake_fd, POLLIN, 0 } };
	const int ready = ::poll(fds, 2, KERNEL_DEVICE_POLL_MS);
	if ((ready < 0 && errno != EINTR) || fds[1].revents != 0) {
		return KernelDeviceWait::STOP;
	}
	return ready > 0 && (fds[0].revents & POLLIN) != 0 ? KernelDeviceWait::READABLE : KernelDeviceWait::IDLE;
}

// "<p_what> <p_object>: <strerror(errno)>", DEVICE_ERROR.
inline Status errno_status(const char *p_what, const std::string &p_object = "") {
	const char *error = std::strerror(errno);
	return Status::error(StatusCode::DEVICE_ERROR, "%s%s%s: %s", p_what, p_object.empty() ? "" : " ", p_object.c_str(), error);
}

} // namespace haptics
