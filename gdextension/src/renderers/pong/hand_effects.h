#pragma once

// The effects the game puts on the device player's hand (bullets and mines, the paper's
// section 3), in that player's device space (x right, y up, z toward the user), newtons:
//   RECOIL, HIT  F = magnitude * direction           for `duration`, no ramp (the paper's
//                                                    transient constant force; the servo's
//                                                    slew limit shapes its edges)
//   SLOW         F = -b v                            v the device velocity; capped
//   HEAVY        F = (0, -magnitude, 0)              down is down on both sides
//   REMOTE       F = k_f (target - p_self)           capped, then the passivity rule
//                                                    below; target = mirror(p_owner + v_owner
//                                                    min(age, max_extrapolation)) low-passed
//                                                    at remote_cutoff_hz
// p_owner is the owner's stylus position in the owner's own device frame (its paddle offset
// over the workspace scale, turned into its frame), mirrored left-right (the paper: so the
// owner steers the victim intuitively), p_self the device position.
//
// REMOTE across the network. The owner's stylus arrives late (60 Hz updates, 0-200 ms), and
// a loop can close through it: both players under each other's remote mine, or an owner
// steering by what it sees of the victim's paddle. A spring to a delayed position is then an
// active element: in such a loop the delay makes each target lag its hand's motion, the
// springs do net work every cycle, and a lightly damped hand oscillates with growing
// amplitude up to the force cap (the doctest's no-passivity case). Two measures:
//   - extrapolation: the sample (position, velocity, age, as the networking delivers them)
//     is moved on by its velocity over its age (at most remote_max_extrapolation_s). It
//     removes most of the lag of a steady motion, but not the loop's: alone it is not enough;
//   - a time-domain passivity observer and controller (Hannaford and Ryu, 2002) at the hand
//     port: E = E_0 - sum(F_k . (x_k+1 - x_k)), the work each tick's force really did while
//     the device held it (booked at the next tick, from the displacement), taken from an
//     allowance E_0 = F_cap^2 / (2 k_f) (what the spring holds at its cap: enough to pull the
//     hand once to the owner's position) and given back whenever the hand works against it,
//     E kept at most 2 E_0. When this tick's predicted work F . v dt (v the present velocity)
//     would take E below 0, a damper along v takes out exactly the excess: F' = F - alpha v,
//     alpha = (F . v dt - max(E, 0)) / (|v|^2 dt), then F' is capped again. Booking F . v dt
//     instead (the velocity of the tick before) was fooled on the simulated device: the held
//     force and the stylus's resonance on the hand beat against the one-tick lag, and the
//     stylus took several times what the observer saw (test_pong_remote_latency.cpp).
//     With the real work booked, the coupling delivers E_0 net plus what the stylus's motion
//     within a tick adds to the controller's prediction: a fraction of a per cent with the
//     simulated device alone (the doctest), about E_0 more in the whole servo at 200 ms
//     round trip against a swinging owner (tests/net/test_net_weapons.py); the figures are in
//     docs/renderers.md. Closing that gap needs a prediction of the tick's displacement (a model of the device and the
//     hand), which this rule does not have.
// Why this and not wave variables: the owner feels no force (the paper's mine is one-way),
// so there is no returning wave to carry, and the remote samples already carry what the
// observer needs; the observer also leaves the paper's feel untouched whenever no energy
// is being pumped (holding against the pull, a slow steer).
// The mine effects (SLOW, HEAVY, REMOTE) ramp linearly in over `ramp` and out over the last
// `ramp` of their duration (halved if the effect is shorter than two ramps).
//
// One slot per kind: a new effect of a kind replaces the running one. No allocation.

#include "core/base/vec3.h"
#include "renderers/pong/court.h"
#include "renderers/pong/pong_config.h"
#include "renderers/pong/pong_input.h"
#include "renderers/pong/pong_output.h"

#include <cstddef>

namespace haptics {

// A player's stylus as this machine last heard of it, that player's device frame: the local
// device's now (age 0), a remote player's as the network delivered it.
struct StylusSample {
	Vec3 position_m;
	Vec3 velocity_m_per_s;
	double age_s = 0.0; // How old the sample is now, s.
};

// An effect with every default resolved, ready to run.
struct EffectOrder {
	PongEffectKind kind = PongEffectKind::NONE;
	Vec3 direction; // Device space, unit (RECOIL, HIT).
	double magnitude_n = 0.0; // RECOIL, HIT, HEAVY: the force; SLOW, REMOTE: a cap (may be inf).
	double duration_s = 0.0;
	double ramp_s = 0.0;
	int owner = 0; // REMOTE.
};

// The effect's envelope p_elapsed_s after it started: ramps in, holds 1, ramps out; 0 from
// p_duration_s on.
double effect_gain(double p_elapsed_s, double p_duration_s, double p_ramp_s);

class HandEffects {
public:
	void configure(const PongConfig &p_config);
	void clear();
	// p_self_m: the device position now (the remote target's low-pass starts there, so its
	// pull grows from zero).
	void start(const EffectOrder &p_order, const Vec3 &p_self_m);
	// The sum of the running effects' forces this tick, then advances them by p_dt_s.
	// p_styluses[i]: player i's stylus in its own device frame (REMOTE's owner).
	Vec3 advance(double p_dt_s, const Vec3 &p_position_m, const Vec3 &p_velocity_m_per_s,
			const StylusSample (&p_styluses)[PONG_MAX_PLAYERS]);
	// The running effects, at most PONG_MAX_ACTIVE_EFFECTS; returns how many.
	size_t list(PongEffectState *r_out) const;
	bool running(PongEffectKind p_kind) const { return slots_[static_cast<size_t>(p_kind)].running; }
	// REMOTE's passivity observer: the energy the coupling may still deliver, J (0 when not
	// running).
	double remote_energy_j() const { return slots_[static_cast<size_t>(PongEffectKind::REMOTE)].energy_j; }
	// REMOTE's low-passed target, device space (the spring's other end).
	Vec3 remote_target_m() const { return slots_[static_cast<size_t>(PongEffectKind::REMOTE)].target_m; }
	// The work REMOTE's force has done on the hand since the last clear(), J: each tick's
	// force as advance() returned it (after the passivity rule) times the displacement the
	// device made while holding it (booked at the next tick). Net: work the hand did against
	// the pull counts negative.
	double remote_work_j() const { return remote_work_j_; }

private:
	struct Slot {
		bool running = false;
		EffectOrder order;
		double elapsed_s = 0.0;
		Vec3 target_m; // REMOTE: the low-passed target.
		double energy_j = 0.0; // REMOTE: the passivity observer's E.
		bool held = false; // REMOTE: the force the device holds until the next tick, from where.
		Vec3 held_force_n;
		Vec3 held_position_m;
	};

	Vec3 force(const Slot &p_slot, double p_gain, const Vec3 &p_position_m, const Vec3 &p_velocity_m_per_s) const;
	double remote_allowance_j(double p_cap_n) const;
	// The passivity rule on a REMOTE force: returns F' and updates the slot's observer.
	Vec3 keep_passive(Slot &r_slot, const Vec3 &p_force_n, const Vec3 &p_position_m, const Vec3 &p_velocity_m_per_s,
			double p_dt_s);

	Slot slots_[PONG_EFFECT_KIND_COUNT]; // By kind; NONE's is never used.
	double slow_damping_n_s_per_m_ = 0.0;
	double remote_stiffness_n_per_m_ = 0.0;
	double remote_cutoff_hz_ = 1.0;
	double remote_max_force_n_ = 0.0;
	double remote_max_extrapolation_s_ = 0.0;
	bool remote_passivity_ = true;
	double remote_work_j_ = 0.0;
};

} // namespace haptics
