#pragma once

// A network correction of the ball (CORRECT_BALL, issue 24). A follower's servo simulates the
// ball between the master's states, and each state, carried to now, corrects it. Put at once
// (SET_BALL) the ball jumped, by up to metres within a tick, and so did the force on a hand
// touching it. Instead the correction is blended in while the ball's physics keeps running
// (its contacts start afresh, pong_sim.h):
//   start     e = target - ball (position, velocity, spin)
//   each tick the ball takes the part s = e (1 - exp(-dt / tau)) of each error, at least the
//             floor |e_0| dt / (FINISH_TIME_CONSTANTS tau) (all of e when less: an exponential
//             alone never ends) and at most the cap; e -= s
// Velocity and spin are taken at once (a change of course, not a jump: the ball is where it
// was), unless the device player's paddle is near. The position's cap is
// correction_max_speed_m_per_s dt, 20 mm a tick at 1 kHz by default (the bound is
// 50 mm), so with a velocity taken at once (at most 2 max_ball_speed dt more) the ball never
// moves more than 38 mm in a tick because of a correction. Uncapped, a correction is over
// within FINISH_TIME_CONSTANTS tau (200 ms by default); capped, within |e_0| / the cap's speed.
// Since the ball keeps its physics and takes the target's velocity, it converges onto the
// corrected trajectory, the one the target's state flies on in this servo.
//
// Near the device player's paddle (the ball could touch it within a tick) the hand would feel
// the correction. Its contact force changes by k_p per metre of penetration, its spin force
// k_hr (w x (a - p)) by k_hr r per rad/s of spin and k_hr max_spin per metre the ball moves,
// so each tick's part is held to half the force budget B = correction_force_rate_n_per_s dt
// (by default the safety stage's slew rate) for the position and half for the spin:
//   |s_p| <= B / (2 (k_p + k_hr max_spin)),   |s_w| <= B / (2 k_hr r),
// and the velocity is blended too (taken at once, it would change the penetration by
// |dv| dt more every tick). The correction then never changes the hand's force faster than
// the slew limit lets the force change.

#include "core/base/vec3.h"
#include "renderers/pong/ball.h"

namespace haptics {

// Without a cap, a correction is over this many time constants after it started.
inline constexpr double CORRECTION_FINISH_TIME_CONSTANTS = 5.0;

// How much of each error a tick may take.
struct CorrectionCaps {
	double position_m = 0.0;
	double spin_rad_per_s = 0.0; // Blended only with blend_velocity_and_spin.
	// The device player's paddle is near: velocity and spin are blended, not taken at once.
	bool blend_velocity_and_spin = false;
};

// One error being blended out: what is left of it and the floor's rate.
struct BlendedError {
	Vec3 left;
	double floor_per_s = 0.0; // |e_0| / (FINISH_TIME_CONSTANTS tau).

	void start(const Vec3 &p_error, double p_time_constant_s);
	// This tick's part (p_share of what is left, the floor, at most p_cap), taken off left.
	Vec3 take(double p_share, double p_dt_s, double p_cap);
	// All of what is left.
	Vec3 take_all();
};

class BallCorrection {
public:
	// A correction of p_ball toward p_target (both as they are now), replacing a running one.
	void start(const BallState &p_ball, const BallState &p_target, double p_time_constant_s);
	void clear();
	bool active() const;
	// Moves r_ball by this tick's part; returns the position's part, m.
	Vec3 advance(BallState &r_ball, double p_dt_s, double p_time_constant_s, const CorrectionCaps &p_caps);
	// The position still to blend in: the corrected ball is at ball + this.
	Vec3 position_left() const { return position_.left; }

private:
	BlendedError position_;
	BlendedError velocity_;
	BlendedError spin_;
};

} // namespace haptics
