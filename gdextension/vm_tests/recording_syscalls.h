#pragma once

// The real evdev system calls, with every EVIOCSFF the backend made kept as the kernel wrote
// it back (the id filled in): what our side put into ff-core, to compare with what reached the
// device model below it.

#include "devices/evdev/evdev_ff.h"
#include "devices/evdev/evdev_syscalls.h"

#include <algorithm>
#include <memory>
#include <mutex>
#include <vector>

namespace haptics::vm {

class RecordingEvdevSyscalls final : public evdev::EvdevSyscalls {
public:
	RecordingEvdevSyscalls() :
			real_(evdev::linux_evdev_syscalls()) {}

	int open_device(const char *p_path) override { return real_->open_device(p_path); }
	int ioctl(int p_fd, uint32_t p_request, void *p_arg) override {
		const int result = real_->ioctl(p_fd, p_request, p_arg);
		if (p_request == evdev::EVDEV_EVIOCSFF && result >= 0) {
			evdev::FfEffectBytes bytes;
			std::copy_n(static_cast<const uint8_t *>(p_arg), bytes.size(), bytes.begin());
			const std::lock_guard lock(mutex_);
			uploads_.push_back(evdev::decode_ff_effect(bytes));
		}
		return result;
	}
	int64_t write(int p_fd, const void *p_bytes, size_t p_size) override { return real_->write(p_fd, p_bytes, p_size); }
	int64_t read(int p_fd, void *r_bytes, size_t p_capacity) override { return real_->read(p_fd, r_bytes, p_capacity); }
	int close(int p_fd) override { return real_->close(p_fd); }

	std::vector<evdev::FfEffectFields> uploads() const {
		const std::lock_guard lock(mutex_);
		return uploads_;
	}

private:
	std::shared_ptr<evdev::EvdevSyscalls> real_;
	mutable std::mutex mutex_;
	std::vector<evdev::FfEffectFields> uploads_;
};

} // namespace haptics::vm
