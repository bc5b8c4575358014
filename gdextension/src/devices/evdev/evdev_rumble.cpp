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

Status EvdevRumble::start(EvdevSyscalls &r_sys, int p_fd, const EvdevFfFeatures &p_features, const char *p_path,
		bool p_take_gain) {
	stop_and_erase();
	envelope_.reset();
	peak_n_.store(0.0, std::memory_order_relaxed);
	FfRumbleEffect effect; // id -1, both motors off, infinite.
	encode_rumble_effect(effect, slot_.bytes());
	const Status started = slot_.start(r_sys, p_fd, p_features, EvdevTakeover{ p_take_gain, false }, "the rumble", p_path);
	effect_ = effect;
	effect_.id = slot_.id();
	return started;
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
	if (!slot_.started()) {
		return -EBADF;
	}
	if (p_levels == current()) {
		return 0;
	}
	FfRumbleEffect next = effect_;
	next.strong_magnitude = p_levels.strong;
	next.weak_magnitude = p_levels.weak;
	encode_rumble_effect(next, slot_.bytes());
	const int result = slot_.upload();
	if (result < 0) {
		return result;
	}
	effect_ = next;
	return 0;
}

int EvdevRumble::stop_and_erase() {
	if (!slot_.started()) {
		return 0;
	}
	const int zeroed = update(FfRumbleLevels{});
	effect_ = FfRumbleEffect{};
	envelope_.reset();
	return slot_.stop_and_erase(zeroed);
}

} // namespace haptics::evdev
