#include "devices/evdev/evdev_syscalls.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/ioctl.h>
#include <unistd.h>

namespace haptics::evdev {

namespace {

// Retries on EINTR: the I/O thread may take a signal meant for the game (profilers, Godot's
// crash handler) and a lost force update would look like a device failure.
class LinuxEvdevSyscalls final : public EvdevSyscalls {
public:
	int open_device(const char *p_path) override {
		int fd;
		do {
			fd = ::open(p_path, O_RDWR | O_NONBLOCK | O_CLOEXEC);
		} while (fd < 0 && errno == EINTR);
		return fd >= 0 ? fd : -errno;
	}

	int ioctl(int p_fd, uint32_t p_request, void *p_arg) override {
		int result;
		do {
			result = ::ioctl(p_fd, static_cast<unsigned long>(p_request), p_arg);
		} while (result < 0 && errno == EINTR);
		return result >= 0 ? result : -errno;
	}

	int64_t write(int p_fd, const void *p_bytes, size_t p_size) override {
		ssize_t written;
		do {
			written = ::write(p_fd, p_bytes, p_size);
		} while (written < 0 && errno == EINTR);
		return written >= 0 ? static_cast<int64_t>(written) : -errno;
	}

	int64_t read(int p_fd, void *r_bytes, size_t p_capacity) override {
		ssize_t count;
		do {
			count = ::read(p_fd, r_bytes, p_capacity);
		} while (count < 0 && errno == EINTR);
		return count >= 0 ? static_cast<int64_t>(count) : -errno;
	}

	int close(int p_fd) override {
		// No retry on EINTR: Linux releases the fd even then, and a retry could close an fd
		// another thread has just been given.
		return ::close(p_fd) == 0 ? 0 : -errno;
	}
};

} // namespace

std::shared_ptr<EvdevSyscalls> linux_evdev_syscalls() {
	return std::make_shared<LinuxEvdevSyscalls>();
}

const char *errno_name(int p_error) {
	const char *name = strerrorname_np(p_error < 0 ? -p_error : p_error);
	return name ? name : "unknown errno";
}

const char *errno_text(int p_error) {
	const char *text = strerrordesc_np(p_error < 0 ? -p_error : p_error);
	return text ? text : "unknown error";
}

} // namespace haptics::evdev
