#pragma once

// The ball-paddle contact law, closed at the servo rate (the paper's section 3).
//
// The paddle is a two-sided disc (centre c, unit normal n, radius R), kinematic: the ball
// never moves the hand. Per tick, for a ball of radius r at p:
//   s     = (p - c).n                 signed distance of the centre to the paddle plane
//   rho   = |(p - c) - s n|           radial distance from the paddle's axis
//   side  = sign of s on the previous tick (remembered through the contact), so a fast
//           ball that crosses the plane within a tick is pushed back out the way it came
//   delta = r - side s                penetration; contact while rho <= R and delta > 0
//   n_s   = side n                    from the paddle toward the ball
//   a     = p - s n                   the ball centre projected onto the paddle plane
//
// Force on the ball, along n_s only (the paper: perpendicular to the paddle, proportional
// to the penetration):   F_b = max(0, k_b delta + b_b d(delta)/dt) n_s.
// The damper b_b is ours: the paper's pure spring never lets a ball settle on a held paddle
// (it rings at omega_n forever). b_b is derived from restitution_paddle (the ratio of
// speeds out and in of a linear spring-damper, e = exp(-pi zeta / sqrt(1 - zeta^2))), and
// the max(0, .) keeps the paddle from ever pulling the ball. The paddle's velocity enters
// through d(delta)/dt and through delta itself: swinging harder sends the ball out faster.
//
// Force on the hand holding the paddle, the paper's two regimes (its |P_p - P_b| read as
// this penetration):   F_h = -n_s (k_p delta if delta <= d, else c).
// Deliberately not the reaction to F_b: the paper found energy-conserving contacts too
// brief to control, and settled on a constant force with a spring zone that stops buzz when
// picking up a resting ball. With c = k_p d (the default) the law is continuous.
//
// Spin, while in contact (w the ball's angular velocity, v_p the paddle's velocity):
//   dw/dt = k_r ((a - p) x v_p) - k_rf w      (the k_r term only in the paddle's spin mode)
//   F_hr  = k_hr (w x (a - p))                on the hand: in the paddle plane, no torque
// The paper writes the levers as (p_ball - a). With w the ball's physical angular velocity
// (the one the court bounces turn into deflections, ball.h) and right-handed axes, that sign
// spins the ball the wrong way (a bat brushing upward behind the ball would give backspin)
// and pushes the hand against the ball's surface motion. (a - p), the lever from the
// centre to the contact point, gives the friction torque's direction and the drag of the
// ball's surface on the paddle. The paper's R_p is the identity: w is already in world axes.
//
// Spin's grip (the paper: later contacts "with walls or paddles" change the ball's velocity
// by its spin). The spin the ball brings into a contact, w_0 (the tick it starts), slips its
// surface over the paddle at u = w_0 x (-r n_s); the paddle's face grips it as the
// court's surfaces do (ball.h), with surface_friction:
//   dv_t  -> -(2/7) u                    over the contact (a sphere that stops slipping)
//   |F_t| <= mu |F_b|                     (Coulomb: no more than friction allows)
// applied as a force on the ball: each tick the part still owed, at most what friction
// allows. Only the spin brought in grips: the spin a brush makes during the contact (the
// k_r term) leaves with the ball and grips on its next contact, so a brush does not push
// the ball against itself. The paddle's own sliding motion still does not drag the ball
// (the paper's push is perpendicular to the paddle), and the spin's loss stays the k_rf
// term.

#include "core/base/vec3.h"
#include "renderers/pong/ball.h"
#include "renderers/pong/pong_config.h"

namespace haptics {

struct PaddlePose {
	Vec3 center; // World, m.
	Vec3 normal; // World, unit.
	Vec3 velocity; // World, m/s.
	bool touchable = false; // Active and not held as a gun.
	bool spin = false; // Spin mode: the paddle's brush spins the ball.
};

// The law's constants, derived once from a PongConfig.
struct PaddleLaw {
	double ball_radius_m = 0.0;
	double paddle_radius_m = 0.0;
	double ball_stiffness_n_per_m = 0.0;
	double ball_damping_n_s_per_m = 0.0; // From restitution_paddle.
	double hand_stiffness_n_per_m = 0.0;
	double spring_range_m = 0.0;
	double contact_force_n = 0.0;
	double spin_gain = 0.0;
	double spin_friction_per_s = 0.0;
	double spin_force_gain = 0.0;
	double ball_mass_kg = 0.0;
	double grip_friction = 0.0; // mu of the spin's grip.
};

PaddleLaw make_paddle_law(const PongConfig &p_config);

// The damping ratio of a linear spring-damper contact whose speed out over speed in is
// p_restitution in [0, 1] (1: none; 0: critical).
double damping_ratio_for_restitution(double p_restitution);

// |F_h|: the hand's force for a penetration p_delta_m >= 0.
double hand_contact_force(double p_delta_m, const PaddleLaw &p_law);

struct PaddleContact {
	bool touching = false;
	bool started = false; // Touching now, not on the previous tick.
	bool released = false; // Touching on the previous tick, not now.
	double penetration_m = 0.0; // delta.
	double approach_speed_m_per_s = 0.0; // max(0, d(delta)/dt): how fast they close in.
	Vec3 toward_ball; // n_s.
	Vec3 anchor; // a.
	Vec3 ball_force_n; // F_b + F_t, world.
	Vec3 grip_force_n; // F_t alone, world.
	Vec3 spin_rate; // dw/dt, world, rad/s^2.
	Vec3 hand_contact_n; // F_h, world.
	Vec3 hand_spin_n; // F_hr, world.
};

// One paddle's memory between ticks: the side of its plane the ball is on, whether they
// touch, and through a contact the spin the ball brought and the grip given so far.
class PaddleContactTracker {
public:
	void reset();
	// p_dt_s: the servo period the ball is integrated with (the grip's per-tick share).
	PaddleContact update(const PaddlePose &p_pose, const BallState &p_ball, const PaddleLaw &p_law, double p_dt_s);
	bool touching() const { return touching_; }
	int side() const { return side_; } // +1, -1; 0 before the first update.

private:
	// F_t for this tick (world), p_toward_ball the face's normal toward the ball; moves the
	// grip given so far on.
	Vec3 grip_force(const Vec3 &p_toward_ball, double p_push_n, const PaddleLaw &p_law, double p_dt_s);

	int side_ = 0;
	bool touching_ = false;
	Vec3 spin_in_; // w_0.
	Vec3 grip_given_; // The grip's dv_t so far this contact, m/s.
};

} // namespace haptics
