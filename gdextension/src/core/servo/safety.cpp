#include "core/servo/safety.h"

#include <algorithm>
#include <cmath>
#include <limits>

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

void SafetyStage::configure(const SafetyConfig &p_config, const SafetyDevice &p_device) {
	config_ = p_config;
	max_force_n_ = p_config.max_force_n > 0.0 ? std::min(p_config.max_force_n, p_device.max_force_n) : p_device.max_force_n;
	const double rating = p_device.max_continuous_force_n > 0.0 ? p_device.max_continuous_force_n
																: std::numeric_limits<double>::infinity();
	max_continuous_n_ = p_config.max_continuous_force_n > 0.0 ? p_config.max_continuous_force_n : rating;
	if (wait_for_small_force_ != p_device.wait_for_small_force) {
		wait_for_small_force_ = p_device.wait_for_small_force;
		holding_ = wait_for_small_force_;
	}
}

void SafetyStage::reset() {
	holding_ = wait_for_small_force_;
	slewed_ = Vec3{};
	ramp_elapsed_s_ = 0.0;
	watchdog_gain_ = 1.0;
}

SafetyResult SafetyStage::apply(const Vec3 &p_smoothed, const Vec3 &p_impact, double p_frame_age_s, double p_dt_s,
		bool p_device_ready) {
	SafetyResult result;

	// 0. Hold. Losing readiness (homing lost) re-arms it.
	if (!p_device_ready) {
		holding_ = true;
	} else if (holding_ && (!wait_for_small_force_ || config_.start_force_n <= 0.0 || (is_finite(p_smoothed) && length(p_smoothed) <= config_.start_force_n))) {
		holding_ = false;
	}
	if (holding_) {
		slewed_ = Vec3{};
		ramp_elapsed_s_ = 0.0;
		result.holding = true;
		result.watchdog_gain = watchdog_gain_;
		result.watchdog_tripped = !(p_frame_age_s <= config_.watchdog_timeout_s);
		return result;
	}

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

	// 2. Continuous cap.
	bool capped = false;
	slewed_ = clamp_magnitude(slewed_, max_continuous_n_, capped);

	// 3. Watchdog.
	result.watchdog_tripped = !(p_frame_age_s <= config_.watchdog_timeout_s);
	const double target = result.watchdog_tripped ? 0.0 : 1.0;
	const double fade_step = config_.watchdog_fade_s > 0.0 ? p_dt_s / config_.watchdog_fade_s : 1.0;
	watchdog_gain_ = approach(watchdog_gain_, target, fade_step);
	result.watchdog_gain = watchdog_gain_;
	result.continuous = slewed_ * watchdog_gain_;

	// 4 + 5. Impacts, then the start-up ramp on everything.
	ramp_elapsed_s_ += p_dt_s;
	result.ramp_gain = config_.startup_ramp_s > 0.0 ? std::min(1.0, ramp_elapsed_s_ / config_.startup_ramp_s) : 1.0;
	if (result.ramp_gain > 1.0 - GAIN_SNAP) {
		result.ramp_gain = 1.0;
	}
	Vec3 impact = p_impact * result.ramp_gain;
	Vec3 total = result.continuous * result.ramp_gain + impact;

	// 6. Non-finite guard.
	if (!is_finite(total)) {
		total = Vec3{};
		impact = Vec3{};
		result.non_finite = true;
	}

	// 7. Clamp; the impact share shrinks with the whole.
	result.total = clamp_magnitude(total, max_force_n_, result.clamped);
	const double magnitude = length(total);
	result.impact = result.clamped && magnitude > 0.0 ? impact * (max_force_n_ / magnitude) : impact;
	result.clamped = result.clamped || capped;
	return result;
}

} // namespace haptics
