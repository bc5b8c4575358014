#include "devices/evdev/evdev_rumble.h"

#include <algorithm>
#include <cerrno>
#include <cmath>

namespace haptics::evdev {

namespace {

uint16_t magnitude_of(double p_fraction) {
	return static_cast<uint16_t>(std::lround(std::clamp(p_fraction, 0.0, 1.0) * 0xffff));
}

} // namespace

FfRumbleLevels RumbleEnvelope::update(double p_peak_n, double p_dt_s, const RumbleMapping &p_mapping) {
	const double peak = std::isfinite(p_peak_n) ? std::fabs(p_peak_n) : 0.0;
	const double input = p_mapping.impact_full_scale_n > 0.0 ? std::min(peak / p_mapping.impact_full_scale_n, 1.0) : 0.0;
	const double kept = p_mapping.release_s > 0.0 ? level_ * std::exp(-std::max(p_dt_s, 0.0) / p_mapping.release_s) : 0.0;
	level_ = std::max(input, kept);
	if (level_ < p_mapping.floor) {
		level_ = 0.0;
	}
	const double knee = p_mapping.strong_motor_knee;
	FfRumbleLevels levels;
	levels.weak = magnitude_of(level_);
	levels.strong = knee < 1.0 ? magnitude_of((level_ - knee) / (1.0 - knee)) : 0;
	return levels;
}

int EvdevRumble::write_event(uint16_t p_code, int32_t p_value) {
	encode_input_event(EVDEV_EV_FF, p_code, p_value, event_);
	const int64_t written = sys_->write(fd_, event_.data(), event_.size());
	if (written < 0) {
		return static_cast<int>(written);
	}
	return written == static_cast<int64_t>(event_.size()) ? 0 : -EIO;
}

int EvdevRumble::upload(FfRumbleEffect &r_effect) {
	encode_rumble_effect(r_effect, bytes_);
	const int result = sys_->ioctl(fd_, EVDEV_EVIOCSFF, bytes_.data());
	if (result < 0) {
		return result;
	}
	r_effect.id = get_s16(bytes_.data(), FF_EFFECT_ID_OFFSET);
	++uploads_;
	return 0;
}

Status EvdevRumble::start(EvdevSyscalls &r_sys, int p_fd, const EvdevFfFeatures &p_features, const char *p_path) {
	stop_and_erase();
	sys_ = &r_sys;
	fd_ = p_fd;
	uploads_ = 0;
	envelope_.reset();
	peak_n_.store(0.0, std::memory_order_relaxed);
	const auto failed = [&](int p_error, const char *p_step) {
		stop_and_erase();
		return Status::error(p_error == -ENODEV ? StatusCode::DEVICE_DISCONNECTED : StatusCode::DEVICE_ERROR,
				"%s: %s failed: %s (%s)", p_path, p_step, errno_text(p_error), errno_name(p_error));
	};
	int result = 0;
	if (p_features.gain && (result = write_event(EVDEV_FF_GAIN, 0xffff)) < 0) {
		return failed(result, "setting the gain (FF_GAIN)");
	}
	FfRumbleEffect effect; // id -1, both motors off, infinite.
	if ((result = upload(effect)) < 0) {
		return failed(result, "uploading the rumble (EVIOCSFF)");
	}
	if (effect.id < 0) {
		return failed(-EINVAL, "uploading the rumble (the kernel returned no effect id)");
	}
	effect_ = effect;
	started_ = true;
	if ((result = write_event(static_cast<uint16_t>(effect_.id), 1)) < 0) {
		return failed(result, "playing the rumble");
	}
	return Status::success();
}

void EvdevRumble::offer_impact(const Vec3 &p_impact_n) {
	const double magnitude = length(p_impact_n);
	if (!std::isfinite(magnitude)) {
		return; // The safety stage zeroes non-finite output: nothing to feel.
	}
	double peak = peak_n_.load(std::memory_order_relaxed);
	while (magnitude > peak && !peak_n_.compare_exchange_weak(peak, magnitude, std::memory_order_relaxed)) {
	}
}

int EvdevRumble::render(double p_dt_s) {
	const double peak = peak_n_.exchange(0.0, std::memory_order_relaxed);
	return update(envelope_.update(peak, p_dt_s, mapping_));
}

int EvdevRumble::update(const FfRumbleLevels &p_levels) {
	if (!started_) {
		return -EBADF;
	}
	if (p_levels == current()) {
		return 0;
	}
	FfRumbleEffect next = effect_;
	next.strong_magnitude = p_levels.strong;
	next.weak_magnitude = p_levels.weak;
	const int result = upload(next);
	if (result < 0) {
		return result;
	}
	effect_ = next;
	return 0;
}

int EvdevRumble::stop_and_erase() {
	if (!started_) {
		return 0;
	}
	// Each step on its own, as EvdevConstantForce::stop_and_erase.
	int first_error = update(FfRumbleLevels{});
	const int stopped = write_event(static_cast<uint16_t>(effect_.id), 0);
	first_error = first_error < 0 ? first_error : stopped;
	const int erased = sys_->ioctl(fd_, EVDEV_EVIOCRMFF, reinterpret_cast<void *>(static_cast<intptr_t>(effect_.id)));
	first_error = first_error < 0 ? first_error : erased;
	started_ = false;
	effect_ = FfRumbleEffect{};
	envelope_.reset();
	return first_error < 0 ? first_error : 0;
}

} // namespace haptics::evdev
