#include "renderers/pong/ball.h"

namespace haptics {

namespace {

// And the angular response to a tangential impulse, r m / I = 5 / (2 r) per unit dv.
constexpr double ANGULAR_PER_TANGENTIAL = 5.0 / 2.0;

} // namespace

Vec3 decrease_length(const Vec3 &p_v, double p_decrease) {
	const double len = length(p_v);
	if (len <= p_decrease) {
		return Vec3{};
	}
	return p_v * ((len - p_decrease) / len);
}

Vec3 cap_length(const Vec3 &p_v, double p_max) {
	const double len = length(p_v);
	return len > p_max ? p_v * (p_max / len) : p_v;
}

void integrate_ball(BallState &r_ball, const Vec3 &p_force_n, const Vec3 &p_spin_rate, bool p_in_contact,
		bool p_beginner, const PongConfig &p_config, double p_dt_s) {
	Vec3 acceleration = p_force_n / p_config.ball_mass_kg;
	if (!p_beginner) {
		acceleration.y -= p_config.gravity_m_per_s2;
	}
	r_ball.velocity += acceleration * p_dt_s;
	r_ball.spin += p_spin_rate * p_dt_s;
	if (!p_in_contact) {
		r_ball.velocity = decrease_length(r_ball.velocity, p_config.air_linear_decel_m_per_s2 * p_dt_s);
		r_ball.spin = decrease_length(r_ball.spin, p_config.air_angular_decel_rad_per_s2 * p_dt_s);
	}
	r_ball.velocity = cap_length(r_ball.velocity, p_config.max_ball_speed_m_per_s);
	r_ball.spin = cap_length(r_ball.spin, p_config.max_spin_rad_per_s);
	if (p_beginner) {
		r_ball.velocity.y = 0.0;
	}
	r_ball.position += r_ball.velocity * p_dt_s;
	if (p_beginner) {
		r_ball.position.y = p_config.beginner_height_m;
	}
}

Bounce bounce_off_plane(BallState &r_ball, const Vec3 &p_normal, double p_restitution, double p_friction,
		double p_radius, double p_rest_speed) {
	Bounce result;
	const double v_n = dot(r_ball.velocity, p_normal);
	if (v_n >= 0.0) {
		return result;
	}
	result.bounced = true;
	result.normal_speed = -v_n;
	double v_n_out = -p_restitution * v_n;
	if (v_n_out < p_rest_speed) {
		v_n_out = 0.0;
		result.resting = true;
	}
	const double normal_impulse = v_n_out - v_n; // Per unit mass: dv_n >= 0.
	const Vec3 v_t = r_ball.velocity - p_normal * v_n;
	const Vec3 slip = v_t + cross(r_ball.spin, p_normal * -p_radius);
	const double stick_impulse = ROLLING_SHARE * length(slip);
	const double friction_limit = p_friction * normal_impulse;
	const Vec3 dv_t = stick_impulse <= friction_limit ? slip * -ROLLING_SHARE
													  : normalized_or_zero(slip) * -friction_limit;
	r_ball.velocity = v_t + dv_t + p_normal * v_n_out;
	r_ball.spin -= cross(p_normal, dv_t) * (ANGULAR_PER_TANGENTIAL / p_radius);
	return result;
}

CourtHits collide_with_court(BallState &r_ball, const PongConfig &p_config, double p_rest_speed) {
	CourtPlane planes[COURT_SURFACE_COUNT];
	court_planes(p_config, planes);
	const double r = p_config.ball_radius_m;
	CourtHits hits;
	for (const CourtPlane &plane : planes) {
		const double gap = dot(plane.normal, r_ball.position) - plane.offset - r;
		if (gap >= 0.0) {
			continue;
		}
		r_ball.position -= plane.normal * gap; // Back inside, touching the surface.
		const double restitution =
				plane.surface == CourtSurface::FLOOR ? p_config.restitution_court : p_config.restitution_wall;
		const Bounce bounce = bounce_off_plane(r_ball, plane.normal, restitution, p_config.surface_friction, r,
				p_rest_speed);
		if (bounce.bounced) {
			hits.hits[hits.count++] = CourtHit{ plane.surface, bounce, r_ball.position };
		}
	}
	return hits;
}

} // namespace haptics
