#pragma once

// The ball: a solid sphere (radius r, mass m) in world space, integrated by semi-implicit
// Euler at the servo period (velocity first, then position with the new velocity: stable
// and nearly energy-preserving for the paddle's spring at omega_n dt = 0.08).
//
// Free flight: gravity -g y (none in beginner mode), and out of contact the paper's air
// friction, a constant decrease of |v| and |w| per second (never below zero, direction
// kept); always |v| <= max_ball_speed and |w| <= max_spin. Beginner mode also holds the
// centre at beginner_height with no vertical velocity (the ball moves in a horizontal plane).
//
// Court surfaces are axis-aligned planes, bounced off by impulses (v_n the normal velocity,
// negative when approaching, n the inward normal):
//   v_n'  = -e v_n                         (0 when that could not lift the ball off the
//                                          surface within a tick: the ball rests)
//   v_c   = v_t + w x (-r n)               slip velocity of the contact point
//   dv_t  = -(2/7) v_c                     if (2/7)|v_c| <= mu dv_n   (the slip stops: rolls)
//         = -mu dv_n unit(v_c)             else (Coulomb: it keeps slipping)
//   dw    = -(5 / (2 r)) (n x dv_t)        the same friction impulse's torque (I = 2/5 m r^2)
// with dv_n = v_n' - v_n, which is (1 + e)|v_n| for a bounce. So topspin (contact point
// moving backward) speeds the ball up on the floor, backspin slows it, and side spin
// deflects it along a wall.

#include "core/base/vec3.h"
#include "renderers/pong/court.h"
#include "renderers/pong/pong_config.h"
#include "renderers/pong/pong_state.gen.h"

namespace haptics {

// Solid sphere: the rolling condition's share of the slip velocity, 1 / (1 + m r^2 / I):
// what friction takes out of a slip before the ball rolls (walls, floor, paddles).
inline constexpr double ROLLING_SHARE = 2.0 / 7.0;

// BallState: pong_state.schema.toml.

// p_v shortened by p_decrease (>= 0), to zero at most; the direction is kept.
Vec3 decrease_length(const Vec3 &p_v, double p_decrease);
// p_v scaled down to p_max if longer.
Vec3 cap_length(const Vec3 &p_v, double p_max);

// One semi-implicit Euler step of p_dt_s under p_force_n (the paddles' push, world) and
// gravity, with the spin changing at p_spin_rate (rad/s^2, the paddles' brush and contact
// friction). p_in_contact: a paddle touches the ball, so no air friction this tick.
void integrate_ball(BallState &r_ball, const Vec3 &p_force_n, const Vec3 &p_spin_rate, bool p_in_contact,
		bool p_beginner, const PongConfig &p_config, double p_dt_s);

struct Bounce {
	bool bounced = false; // The ball was approaching the surface.
	bool resting = false; // It was too slow to leave it again: normal velocity zeroed.
	double normal_speed = 0.0; // |v_n| before the bounce, m/s.
};

// The impulse bounce above off a plane with inward unit normal p_normal. Leaves the ball
// alone (bounced false) when it is not approaching. p_rest_speed: an outgoing normal speed
// below it is zeroed (gravity * dt: the ball could not rise off the surface within a tick).
Bounce bounce_off_plane(BallState &r_ball, const Vec3 &p_normal, double p_restitution, double p_friction,
		double p_radius, double p_rest_speed);

struct CourtHit {
	CourtSurface surface;
	Bounce bounce;
	Vec3 position; // The ball centre once pushed back inside.
};

struct CourtHits {
	CourtHit hits[COURT_SURFACE_COUNT];
	int count = 0;
};

// Bounces the ball off every court surface it overlaps while approaching, and puts it back
// inside the court. p_rest_speed as above.
CourtHits collide_with_court(BallState &r_ball, const PongConfig &p_config, double p_rest_speed);

} // namespace haptics
