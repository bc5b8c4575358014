#pragma once

// The effects the game puts on the device player's hand (bullets and mines, the paper's
// section 3), in that player's device space (x right, y up, z toward the user), newtons:
//   RECOIL, HIT  F = magnitude * direction           for `duration`, no ramp (the paper's
//                                                    transient constant force; the servo's
//                                                    slew limit shapes its edges)
//   SLOW         F = -b v                            v the device velocity; capped
//   HEAVY        F = (0, -magnitude, 0)              down is down on both sides
//   REMOTE       F = k_f (target - p_self)           capped; target = mirror(p_owner)
//                                                    low-passed at remote_cutoff_hz
// p_owner is the owner's stylus position in the owner's own device frame (its paddle offset
// over the workspace scale, turned into its frame), mirrored left-right (the paper: so the
// owner steers the victim intuitively), p_self the device position. Only the victim feels
// it: the owner's position is an external reference, no force loop closes over the network.
// The mine effects (SLOW, HEAVY, REMOTE) ramp linearly in over `ramp` and out over the last
// `ramp` of their duration (halved if the effect is shorter than two ramps).
//
// One slot per kind: a new effect of a kind replaces the running one. No allocation.

#include "core/vec3.h"
#include "pong/court.h"
#include "pong/pong_config.h"
#include "pong/pong_input.h"
#include "pong/pong_output.h"

#include <cstddef>

namespace haptics {

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
			const Vec3 (&p_styluses)[PONG_MAX_PLAYERS]);
	// The running effects, at most PONG_MAX_ACTIVE_EFFECTS; returns how many.
	size_t list(PongEffectState *r_out) const;
	bool running(PongEffectKind p_kind) const { return slots_[static_cast<size_t>(p_kind)].running; }

private:
	struct Slot {
		bool running = false;
		EffectOrder order;
		double elapsed_s = 0.0;
		Vec3 target_m; // REMOTE: the low-passed target.
	};

	Vec3 force(const Slot &p_slot, double p_gain, const Vec3 &p_position_m, const Vec3 &p_velocity_m_per_s) const;

	Slot slots_[PONG_EFFECT_KIND_COUNT]; // By kind; NONE's is never used.
	double slow_damping_n_s_per_m_ = 0.0;
	double remote_stiffness_n_per_m_ = 0.0;
	double remote_cutoff_hz_ = 1.0;
};

} // namespace haptics
