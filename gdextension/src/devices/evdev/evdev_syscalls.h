#pragma once

// The seam between the evdev backend and the kernel: the five calls it makes on
// /dev/input/eventN, with the kernel's error convention (a negative errno instead of -1 and
// errno, so the seam is thread-safe and a scripted kernel can return errors without
// touching the global). linux_evdev_syscalls() is the real one; ScriptedEvdevKernel
// (dev_tools/evdev/scripted_evdev_kernel.h) answers like the kernel does, for tests and the
// benchmark.

#include <cstddef>
#include <cstdint>
#include <memory>

namespace haptics::evdev {

class EvdevSyscalls {
public:
	virtual ~EvdevSyscalls() = default;

	// open(p_path, O_RDWR | O_NONBLOCK | O_CLOEXEC): an fd, or -errno (-ENOENT: no such
	// node, -EACCES: no permission, -ENODEV: the device went away).
	virtual int open_device(const char *p_path) = 0;
	// ioctl(p_fd, p_request, p_arg): >= 0 on success (EVIOCGBIT and EVIOCGNAME return the
	// byte count copied), or -errno. EVIOCRMFF takes the effect id cast to a pointer.
	virtual int ioctl(int p_fd, uint32_t p_request, void *p_arg) = 0;
	// Bytes written (whole 24-byte input_events), or -errno.
	virtual int64_t write(int p_fd, const void *p_bytes, size_t p_size) = 0;
	// Non-blocking: bytes read (whole input_events from a real kernel), -EAGAIN when nothing
	// is pending, -ENODEV once the device is gone.
	virtual int64_t read(int p_fd, void *r_bytes, size_t p_capacity) = 0;
	// 0 or -errno; the fd is released either way (the kernel then erases the effects this
	// fd uploaded, as ff.rst says effects belong to the file).
	virtual int close(int p_fd) = 0;
};

// The real system calls. Stateless; the shared pointer only makes ownership uniform with
// the scripted kernel.
std::shared_ptr<EvdevSyscalls> linux_evdev_syscalls();

// "ENODEV" and "No such device" for p_error (positive or negative); never null, no
// allocation, safe on any thread (glibc's strerrorname_np/strerrordesc_np tables).
const char *errno_name(int p_error);
const char *errno_text(int p_error);

} // namespace haptics::evdev
