#include "renderers/pong/paddle_contact.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace haptics {

double damping_ratio_for_restitution(double p_restitution) {
	if (p_restitution <= 0.0) {
		return 1.0;
	}
	const double log_e = std::log(std::min(p_restitution, 1.0));
	return -log_e / std::sqrt(std::numbers::pi * std::numbers::pi + log_e * log_e);
}

PaddleLaw make_paddle_law(const PongConfig &p_config) {
	PaddleLaw law;
	law.ball_radius_m = p_config.ball_radius_m;
	law.paddle_radius_m = p_config.paddle_radius_m;
	law.ball_stiffness_n_per_m = p_config.ball_stiffness_n_per_m;
	law.ball_damping_n_s_per_m = 2.0 * damping_ratio_for_restitution(p_config.restitution_paddle) *
			std::sqrt(p_config.ball_stiffness_n_per_m * p_config.ball_mass_kg);
	law.hand_stiffness_n_per_m = p_config.hand_stiffness_n_per_m;
	law.spring_range_m = p_config.spring_range_m;
	law.contact_force_n = p_config.contact_force_n;
	law.spin_gain = p_config.spin_gain;
	law.spin_friction_per_s = p_config.spin_friction_per_s;
	law.spin_force_gain = p_config.spin_force_gain;
	law.ball_mass_kg = p_config.ball_mass_kg;
	law.grip_friction = p_config.surface_friction;
	return law;
}

double hand_contact_force(double p_delta_m, const PaddleLaw &p_law) {
	return p_delta_m <= p_law.spring_range_m ? p_law.hand_stiffness_n_per_m * p_delta_m : p_law.contact_force_n;
}

void PaddleContactTracker::reset() {
	side_ = 0;
	touching_ = false;
	spin_in_ = Vec3{};
	grip_given_ = Vec3{};
}

PaddleContact PaddleContactTracker::update(
		const PaddlePose &p_pose, const BallState &p_ball, const PaddleLaw &p_law, double p_dt_s) {
	PaddleContact contact;
	const Vec3 offset = p_ball.position - p_pose.center;
	const double s = dot(offset, p_pose.normal);
	const double rho = length(offset - p_pose.normal * s);
	const int now_side = s >= 0.0 ? 1 : -1;
	const int side = side_ != 0 ? side_ : now_side;
	const double delta = p_law.ball_radius_m - side * s;
	contact.touching = p_pose.touchable && rho <= p_law.paddle_radius_m && delta > 0.0;
	contact.started = contact.touching && !touching_;
	contact.released = !contact.touching && touching_;
	touching_ = contact.touching;
	// Through a contact the side it began on holds; outside one it follows the ball.
	side_ = contact.touching ? side : now_side;
	if (!contact.touching) {
		return contact;
	}
	contact.penetration_m = delta;
	contact.toward_ball = p_pose.normal * static_cast<double>(side);
	contact.anchor = p_ball.position - p_pose.normal * s;
	// d(delta)/dt = -(v_ball - v_paddle).n_s: positive while the two close in.
	const double closing_speed = -dot(p_ball.velocity - p_pose.velocity, contact.toward_ball);
	contact.approach_speed_m_per_s = std::max(0.0, closing_speed);
	const double push = std::max(
			0.0, p_law.ball_stiffness_n_per_m * delta + p_law.ball_damping_n_s_per_m * closing_speed);
	const Vec3 lever = contact.anchor - p_ball.position; // Centre -> contact point.
	if (contact.started) {
		spin_in_ = p_ball.spin;
		grip_given_ = Vec3{};
	}
	contact.grip_force_n = grip_force(contact.toward_ball, push, p_law, p_dt_s);
	contact.ball_force_n = contact.toward_ball * push + contact.grip_force_n;

	contact.spin_rate = p_ball.spin * -p_law.spin_friction_per_s;
	if (p_pose.spin) {
		contact.spin_rate += cross(lever, p_pose.velocity) * p_law.spin_gain;
	}
	contact.hand_contact_n = contact.toward_ball * -hand_contact_force(delta, p_law);
	contact.hand_spin_n = cross(p_ball.spin, lever) * p_law.spin_force_gain;
	return contact;
}

Vec3 PaddleContactTracker::grip_force(
		const Vec3 &p_toward_ball, double p_push_n, const PaddleLaw &p_law, double p_dt_s) {
	if (p_dt_s <= 0.0 || p_law.ball_mass_kg <= 0.0) {
		return Vec3{};
	}
	// The ball's surface where it meets the face, a full radius from its centre (even when a
	// fast ball has crossed the plane within a tick).
	const Vec3 lever = p_toward_ball * -p_law.ball_radius_m;
	const Vec3 owed = cross(spin_in_, lever) * -ROLLING_SHARE - grip_given_;
	const double owed_speed = length(owed);
	const double allowed_speed = p_law.grip_friction * p_push_n * p_dt_s / p_law.ball_mass_kg;
	const Vec3 step = owed_speed <= allowed_speed ? owed : owed * (allowed_speed / owed_speed);
	grip_given_ += step;
	return step * (p_law.ball_mass_kg / p_dt_s);
}

} // namespace haptics
