#pragma once

// Haptic Battle Pong's constants: the court, the ball, the paddle contact law, spin, air
// friction and the mine/bullet effects. The Pong renderer's settings, section "pong" of the
// game's configuration; each field's key, range and unit are in its row of the field table
// (pong_config_fields.cpp). The defaults are tuned for the simulated Omni-like stylus (3.3 N
// peak, 0.10 m workspace radius, CHAI3D's stable 700 N/m); the comment on each says why it
// has that value.
//
// World space is Godot's 3D world: metres, y up, the court floor at y = 0 (court.h).

#include "core/servo/servo_config.h"

namespace haptics {

struct PongConfig {
	// --- Court --------------------------------------------------------------------------
	// 2 (the paper's match: a rectangle split at z = 0) or 4 (a square court, one back wall
	// each, territories split by the diagonals; court.h). Key "players".
	int players = 2;
	// 3 m x 6 m x 2.5 m: each half is 3 m x 3 m, which a 0.5 m paddle reach plus an avatar
	// walking at game speed covers, and the ball has room to curve between bounces.
	double court_half_width_m = 1.5;
	double court_half_length_m = 3.0;
	double wall_height_m = 2.5; // The paper's court is enclosed on all sides: walls and ceiling.

	// World metres of paddle travel per metre of stylus travel: 0.1 m of stylus reach
	// becomes 0.5 m of paddle reach, enough to meet a ball half a metre off the avatar.
	double workspace_scale = 5.0;

	// --- Ball and paddle -----------------------------------------------------------------
	// A 0.44 m disc against a 0.14 m ball: large enough for novices to meet the ball (the
	// paper's hardest skill is judging depth), small enough that placing it matters.
	double paddle_radius_m = 0.22;
	double ball_radius_m = 0.07;
	double ball_mass_kg = 0.06;
	// Below 9.81 on purpose: a longer flight leaves novices time to judge depth.
	double gravity_m_per_s2 = 6.0;

	// --- Contact law ---------------------------------------------------------------------
	// The ball-side spring. With 0.06 kg the contact half period pi sqrt(m/k) is 38 ms, 38
	// servo ticks, and omega_n dt = 0.08: well resolved by semi-implicit Euler at 1 kHz.
	double ball_stiffness_n_per_m = 400.0;
	// How lively the paddle is (ball speed out / in, paddle at rest). The paper's contact is a
	// pure spring, which never lets a ball come to rest on a held paddle (it rings forever
	// at omega_n); a matching damper, derived from this (paddle_contact.h), settles it in
	// about a second. 0.8 is a table-tennis bat's rubber.
	double restitution_paddle = 0.8;
	// k_p of the hand's force: N per metre of WORLD penetration, felt at the device as
	// k_p * workspace_scale = 200 N/m, 0.29 x the Omni's 700 N/m (CHAI3D examples use
	// 0.2-0.5 x): stiff enough to feel, far from the stability limit.
	double hand_stiffness_n_per_m = 40.0;
	// d: the spring regime of the hand's force ends at 4 cm of penetration, about the depth
	// a 2 m/s hit reaches (v / omega_n); below it the hand feels a spring, which stops the
	// buzz of picking up a resting ball (the paper's reason for the spring zone).
	double spring_range_m = 0.04;
	// c: the constant hand force beyond d. Default k_p d, so the law is continuous at d; the
	// paper's jump (c != k_p d) makes a penetration hovering around d chatter by |c - k_p d|.
	// Kept as its own field so the paper's variant can be configured. 1.6 N leaves headroom
	// under the 3.3 N peak for the spin force and the transients.
	double contact_force_n = hand_stiffness_n_per_m * spring_range_m;

	// --- Court surfaces -----------------------------------------------------------------
	double restitution_court = 0.85; // A table-tennis ball on a table.
	double restitution_wall = 0.9; // Walls a little livelier than the floor: rallies last.
	// Coulomb friction at court bounces and of a paddle's face on the spin a ball brings
	// (paddle_contact.h): what turns spin into a change of direction, the paper's "spin
	// deflects the ball on later contacts with walls or paddles". 0.35 lets a 20 rad/s spin
	// bend the bounce visibly without making every bounce a skid.
	double surface_friction = 0.35;
	// Slower floor touches are the ball rolling or settling, not bounces: no FLOOR event (a
	// rolling ball must not cost a life on every tick).
	double min_bounce_speed_m_per_s = 0.8;

	// --- Spin ---------------------------------------------------------------------------
	// k_r, rad/s^2 per (m * m/s): a 2 m/s brush over a 38 ms contact with the ball centre
	// 0.07 m off the paddle gives about 20 rad/s, a surface speed of 1.4 m/s: a visible
	// curve on the next bounce.
	double spin_gain = 4000.0;
	// k_rf, 1/s: contact friction eats spin with a 125 ms time constant, longer than a
	// contact (so a brush keeps most of what it made) and short enough that a ball resting on
	// a paddle stops spinning within a second.
	double spin_friction_per_s = 8.0;
	// k_hr, N per (rad/s * m): the spin force on the receiving hand, 0.08 x 120 rad/s x
	// 0.07 m = 0.67 N at the cap: felt, yet well under the contact force.
	double spin_force_gain = 0.08;
	double max_spin_rad_per_s = 120.0; // Keeps the spin force and the deflections bounded.

	// --- Air ----------------------------------------------------------------------------
	// The paper's non-linear air friction: a constant decrease of |v| and |w| out of contact,
	// which slows fast balls as much as slow ones (a mass increase would not: small stylus
	// motions could then no longer move the ball).
	double air_linear_decel_m_per_s2 = 0.6;
	double air_angular_decel_rad_per_s2 = 4.0;
	// The paper's absolute cap: 9 m/s crosses the court in 0.7 s, still returnable; it also
	// bounds the ball's travel per tick (9 mm, an eighth of its radius), so contacts are
	// never skipped.
	double max_ball_speed_m_per_s = 9.0;

	// --- Effects on the device player's hand (device space) -----------------------------
	// Bullets: the paper's transient constant force, along the gun axis away from the bullet
	// (recoil) and along the bullet on a hit. Short (80-120 ms) and below the 3.3 N peak, so
	// the slew limit shapes their edges and they never clip.
	double recoil_force_n = 1.2;
	double recoil_duration_s = 0.08;
	double hit_force_n = 1.5;
	double hit_duration_s = 0.12;
	// Mines (slow, heavy, remote): 4 s, long enough to fight, ramped over 0.25 s at both ends
	// so they never kick the hand.
	double mine_effect_duration_s = 4.0;
	double mine_effect_ramp_s = 0.25;
	// Slow paddle, F = -b v on the device velocity. The spec's 6 N s/m is above what is safe:
	// half the Omni's 5 N s/m damping limit is 2.5, and 2.0 keeps a margin.
	double slow_damping_n_s_per_m = 2.0;
	double heavy_force_n = 1.0; // Heavy paddle: a weight the hand holds up, under the 3.3 N peak.
	// Remote paddle, F = k_f (mirror(p_owner) - p_self): 120 N/m pulls 1.5 N at 12.5 mm off
	// the owner's mirrored stylus. One-way (only the victim feels it), so no force loop closes
	// over the network; the target is low-passed at 6 Hz (network updates arrive at frame
	// rate) and the force capped, so a fast owner cannot inject energy.
	double remote_stiffness_n_per_m = 120.0;
	double remote_cutoff_hz = 6.0;
	double remote_max_force_n = 1.5;
	// The owner's stylus arrives late over the network (60 Hz, 0-200 ms): the target is moved
	// on by the reported velocity over the sample's age, at most this long (a stale sample of
	// a fast owner must not fling the target across the workspace).
	double remote_max_extrapolation_s = 0.2;
	// The time-domain passivity rule on the remote coupling (hand_effects.h). Off only to show
	// what it prevents (a doctest keeps that case): a delayed coupling then pumps energy.
	bool remote_passivity = true;

	// --- Network corrections of the ball (CORRECT_BALL, ball_correction.h) ---------------
	// A follower's ball is blended onto the master's with this time constant: 95 % of an
	// error is gone after 3 tau (120 ms), all of it after 5 tau unless the cap below holds it.
	double correction_time_constant_s = 0.04;
	// The blend moves the ball at most this fast: 20 mm a tick at 1 kHz, well under the
	// issue's 50 mm; a 2.5 m correction (a missed hand-off) is a 125 ms glide, not a jump.
	double correction_max_speed_m_per_s = 20.0;
	// Near the device player's paddle a correction changes the hand's force no faster than
	// this: the safety stage's default slew rate, so the slew limit never has to clip one.
	double correction_force_rate_n_per_s = SafetyConfig{}.slew_rate_n_per_s;

	// --- Beginner mode (the paper's "Haptic Battle Air Hockey") -------------------------
	// No gravity; the ball centre is held at this height, about a seated player's paddle.
	double beginner_height_m = 0.9;
	// The target the game draws on each back wall: centred, this half width, floor to
	// ceiling. The game scores it from the back-wall WALL events; it lives here so the game
	// and the servo agree on one number.
	double beginner_target_half_width_m = 0.5;
};

} // namespace haptics
