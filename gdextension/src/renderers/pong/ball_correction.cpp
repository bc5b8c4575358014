#include "renderers/pong/ball_correction.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace haptics {

void BlendedError::start(const Vec3 &p_error, double p_time_constant_s) {
	left = p_error;
	floor_per_s = length(p_error) / (CORRECTION_FINISH_TIME_CONSTANTS * p_time_constant_s);
}

Vec3 BlendedError::take(double p_share, double p_dt_s, double p_cap) {
	const double size = length(left);
	if (size == 0.0) {
		return Vec3{};
	}
	const double part = std::min({ std::max(p_share * size, floor_per_s * p_dt_s), size, p_cap });
	if (part >= size) {
		return take_all(); // Exactly zero left, not a rounding residue.
	}
	const Vec3 step = left * (part / size);
	left -= step;
	return step;
}

Vec3 BlendedError::take_all() {
	const Vec3 all = left;
	left = Vec3{};
	return all;
}

void BallCorrection::start(const BallState &p_ball, const BallState &p_target, double p_time_constant_s) {
	position_.start(p_target.position - p_ball.position, p_time_constant_s);
	velocity_.start(p_target.velocity - p_ball.velocity, p_time_constant_s);
	spin_.start(p_target.spin - p_ball.spin, p_time_constant_s);
}

void BallCorrection::clear() {
	position_ = BlendedError{};
	velocity_ = BlendedError{};
	spin_ = BlendedError{};
}

bool BallCorrection::active() const {
	const Vec3 zero{};
	return position_.left != zero || velocity_.left != zero || spin_.left != zero;
}

Vec3 BallCorrection::advance(BallState &r_ball, double p_dt_s, double p_time_constant_s, const CorrectionCaps &p_caps) {
	const double share = 1.0 - std::exp(-p_dt_s / p_time_constant_s);
	if (p_caps.blend_velocity_and_spin) {
		r_ball.velocity += velocity_.take(share, p_dt_s, std::numeric_limits<double>::infinity());
		r_ball.spin += spin_.take(share, p_dt_s, p_caps.spin_rad_per_s);
	} else {
		r_ball.velocity += velocity_.take_all();
		r_ball.spin += spin_.take_all();
	}
	const Vec3 step = position_.take(share, p_dt_s, p_caps.position_m);
	r_ball.position += step;
	return step;
}

} // namespace haptics
