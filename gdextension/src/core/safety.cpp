#include "core/safety.h"

#include <algorithm>
#include <cmath>

namespace haptics {

namespace {

// Gains this close to 0 or 1 are snapped, so a fade ends exactly where it should rather than
// one tick later because dt / fade_s does not sum to exactly 1 in floating point.
constexpr double GAIN_SNAP = 1e-9;

double approach(double p_value, double p_target, double p_step) {
	double next = p_value < p_target ? std::min(p_target, p_value + p_step) : std::max(p_target, p_value - p_step);
	if (std::abs(next - p_target) < GAIN_SNAP) {
		next = p_target;
	}
	return next;
}

} // namespace

Vec3 clamp_magnitude(const Vec3 &p_force, double p_max_n, bool &r_clamped) {
	const double magnitude = length(p_force);
	r_clamped = magnitude > p_max_n;
	if (!r_clamped) {
		return p_force;
	}
	return magnitude > 0.0 ? p_force * (p_max_n / magnitude) : Vec3{};
}

void SafetyStage::configure(const SafetyConfig &p_config, double p_device_max_force_n) {
	config_ = p_config;
	max_force_n_ = p_config.max_force_n > 0.0 ? std::min(p_config.max_force_n, p_device_max_force_n) : p_device_max_force_n;
}

void SafetyStage::reset() {
	slewed_ = Vec3{};
	ramp_elapsed_s_ = 0.0;
	watchdog_gain_ = 1.0;
}

SafetyResult SafetyStage::apply(const Vec3 &p_smoothed, const Vec3 &p_impact, double p_frame_age_s, double p_dt_s) {
	SafetyResult result;

	// 1. Slew limit. A non-finite input resets the limiter instead of poisoning it.
	if (!is_finite(p_smoothed)) {
		slewed_ = Vec3{};
		result.non_finite = true;
	} else if (config_.slew_rate_n_per_s > 0.0) {
		const Vec3 delta = p_smoothed - slewed_;
		const double step = length(delta);
		const double max_step = config_.slew_rate_n_per_s * p_dt_s;
		slewed_ = step > max_step ? slewed_ + delta * (max_step / step) : p_smoothed;
	} else {
		slewed_ = p_smoothed;
	}

	// 2. Watchdog.
	result.watchdog_tripped = !(p_frame_age_s <= config_.watchdog_timeout_s);
	const double target = result.watchdog_tripped ? 0.0 : 1.0;
	const double fade_step = config_.watchdog_fade_s > 0.0 ? p_dt_s / config_.watchdog_fade_s : 1.0;
	watchdog_gain_ = approach(watchdog_gain_, target, fade_step);
	result.watchdog_gain = watchdog_gain_;
	result.continuous = slewed_ * watchdog_gain_;

	// 3 + 4. Impacts, then the start-up ramp on everything.
	ramp_elapsed_s_ += p_dt_s;
	result.ramp_gain = config_.startup_ramp_s > 0.0 ? std::min(1.0, ramp_elapsed_s_ / config_.startup_ramp_s) : 1.0;
	if (result.ramp_gain > 1.0 - GAIN_SNAP) {
		result.ramp_gain = 1.0;
	}
	Vec3 total = (result.continuous + p_impact) * result.ramp_gain;

	// 5. Non-finite guard.
	if (!is_finite(total)) {
		total = Vec3{};
		result.non_finite = true;
	}

	// 6. Clamp.
	result.total = clamp_magnitude(total, max_force_n_, result.clamped);
	return result;
}

} // namespace haptics
