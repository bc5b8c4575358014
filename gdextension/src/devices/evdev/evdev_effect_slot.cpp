#include "devices/evdev/evdev_effect_slot.h"

#include "devices/evdev/evdev_effect.h"

#include <cerrno>
#include <cstdio>

namespace haptics::evdev {

Status EvdevEffectSlot::start(EvdevSyscalls &r_sys, int p_fd, const EvdevFfFeatures &p_features,
		const EvdevTakeover &p_takeover, const char *p_what, const char *p_path) {
	stop_and_erase();
	sys_ = &r_sys;
	fd_ = p_fd;
	id_ = -1;
	uploads_ = 0;
	// p_step: what was being done, with %s for p_what where it names the effect.
	const auto failed = [&](int p_error, const char *p_step) {
		stop_and_erase();
		char step[128];
		std::snprintf(step, sizeof(step), p_step, p_what);
		return Status::error(p_error == -ENODEV ? StatusCode::DEVICE_DISCONNECTED : StatusCode::DEVICE_ERROR,
				"%s: %s failed: %s (%s)", p_path, step, errno_text(p_error), errno_name(p_error));
	};
	int result = 0;
	if (p_takeover.gain && p_features.gain && (result = write_event(EVDEV_FF_GAIN, 0xffff)) < 0) {
		return failed(result, "setting the gain (FF_GAIN)");
	}
	if (p_takeover.spring && p_features.autocenter && (result = write_event(EVDEV_FF_AUTOCENTER, 0)) < 0) {
		return failed(result, "turning autocentre off (FF_AUTOCENTER)");
	}
	if ((result = send_upload()) < 0) {
		return failed(result, "uploading %s (EVIOCSFF)");
	}
	if (id_ < 0) {
		return failed(-EINVAL, "uploading %s (the kernel returned no effect id)");
	}
	started_ = true;
	if ((result = write_event(static_cast<uint16_t>(id_), 1)) < 0) {
		return failed(result, "playing %s");
	}
	return Status::success();
}

int EvdevEffectSlot::upload() {
	return started_ ? send_upload() : -EBADF;
}

int EvdevEffectSlot::replay() {
	return started_ ? write_event(static_cast<uint16_t>(id_), 1) : -EBADF;
}

int EvdevEffectSlot::send_upload() {
	put_u16(bytes_.data(), FF_EFFECT_ID_OFFSET, static_cast<uint16_t>(id_));
	const int result = sys_->ioctl(fd_, EVDEV_EVIOCSFF, bytes_.data());
	if (result < 0) {
		return result;
	}
	// The kernel writes the id it chose back into the struct (always the same on update).
	id_ = get_s16(bytes_.data(), FF_EFFECT_ID_OFFSET);
	++uploads_;
	return 0;
}

int EvdevEffectSlot::stop_and_erase(int p_first_error) {
	if (!started_) {
		return 0;
	}
	// Each step on its own: an unplugged device fails them all, and a zero upload that
	// failed must not keep the effect from being stopped and erased.
	int first_error = p_first_error;
	const int stopped = write_event(static_cast<uint16_t>(id_), 0);
	first_error = first_error < 0 ? first_error : stopped;
	const int erased = sys_->ioctl(fd_, EVDEV_EVIOCRMFF, reinterpret_cast<void *>(static_cast<intptr_t>(id_)));
	first_error = first_error < 0 ? first_error : erased;
	started_ = false;
	id_ = -1;
	return first_error < 0 ? first_error : 0;
}

int EvdevEffectSlot::write_event(uint16_t p_code, int32_t p_value) {
	encode_input_event(EVDEV_EV_FF, p_code, p_value, event_);
	const int64_t written = sys_->write(fd_, event_.data(), event_.size());
	if (written < 0) {
		return static_cast<int>(written);
	}
	return written == static_cast<int64_t>(event_.size()) ? 0 : -EIO;
}

} // namespace haptics::evdev
