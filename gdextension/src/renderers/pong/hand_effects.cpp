#include "renderers/pong/hand_effects.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace haptics {

double effect_gain(double p_elapsed_s, double p_duration_s, double p_ramp_s) {
	if (p_elapsed_s < 0.0 || p_elapsed_s >= p_duration_s) {
		return 0.0;
	}
	const double ramp = std::min(p_ramp_s, 0.5 * p_duration_s);
	if (ramp <= 0.0) {
		return 1.0;
	}
	return std::clamp(std::min(p_elapsed_s, p_duration_s - p_elapsed_s) / ramp, 0.0, 1.0);
}

void HandEffects::configure(const PongConfig &p_config) {
	slow_damping_n_s_per_m_ = p_config.slow_damping_n_s_per_m;
	remote_stiffness_n_per_m_ = p_config.remote_stiffness_n_per_m;
	remote_cutoff_hz_ = p_config.remote_cutoff_hz;
	remote_max_force_n_ = p_config.remote_max_force_n;
	remote_max_extrapolation_s_ = p_config.remote_max_extrapolation_s;
	remote_passivity_ = p_config.remote_passivity;
}

void HandEffects::clear() {
	for (Slot &slot : slots_) {
		slot = Slot{};
	}
	remote_work_j_ = 0.0;
}

void HandEffects::start(const EffectOrder &p_order, const Vec3 &p_self_m) {
	if (p_order.kind == PongEffectKind::NONE) {
		return;
	}
	Slot &slot = slots_[static_cast<size_t>(p_order.kind)];
	slot.running = true;
	slot.order = p_order;
	slot.elapsed_s = 0.0;
	slot.target_m = p_self_m;
	if (p_order.kind == PongEffectKind::REMOTE) {
		slot.energy_j = remote_allowance_j(p_order.magnitude_n);
	}
}

double HandEffects::remote_allowance_j(double p_cap_n) const {
	// What the spring holds stretched to its cap; an uncapped order uses the config's cap.
	const double cap = std::isfinite(p_cap_n) ? std::min(p_cap_n, remote_max_force_n_) : remote_max_force_n_;
	return remote_stiffness_n_per_m_ > 0.0 ? 0.5 * cap * cap / remote_stiffness_n_per_m_ : 0.0;
}

Vec3 HandEffects::keep_passive(Slot &r_slot, const Vec3 &p_force_n, const Vec3 &p_position_m,
		const Vec3 &p_velocity_m_per_s, double p_dt_s) {
	const double ceiling = 2.0 * remote_allowance_j(r_slot.order.magnitude_n);
	// The observer books the work the last tick's force really did: the device held it over
	// the step that brought the stylus here.
	if (r_slot.held) {
		const double done = dot(r_slot.held_force_n, p_position_m - r_slot.held_position_m);
		remote_work_j_ += done;
		r_slot.energy_j = std::min(r_slot.energy_j - done, ceiling);
	}
	// The controller limits this tick's force by the work it would do at the present velocity.
	Vec3 force = p_force_n;
	const double delivered = dot(force, p_velocity_m_per_s) * p_dt_s;
	const double speed_squared = length_squared(p_velocity_m_per_s);
	if (remote_passivity_ && delivered > r_slot.energy_j && speed_squared > 0.0) {
		const double alpha = (delivered - std::max(r_slot.energy_j, 0.0)) / (speed_squared * p_dt_s);
		force = cap_length(force - p_velocity_m_per_s * alpha, r_slot.order.magnitude_n);
	}
	r_slot.held = true;
	r_slot.held_force_n = force;
	r_slot.held_position_m = p_position_m;
	return force;
}

Vec3 HandEffects::force(const Slot &p_slot, double p_gain, const Vec3 &p_position_m,
		const Vec3 &p_velocity_m_per_s) const {
	const EffectOrder &order = p_slot.order;
	switch (order.kind) {
		case PongEffectKind::RECOIL:
		case PongEffectKind::HIT:
			return order.direction * (order.magnitude_n * p_gain);
		case PongEffectKind::SLOW:
			return cap_length(p_velocity_m_per_s * (-slow_damping_n_s_per_m_ * p_gain), order.magnitude_n);
		case PongEffectKind::HEAVY:
			return Vec3{ 0.0, -order.magnitude_n * p_gain, 0.0 };
		case PongEffectKind::REMOTE:
			return cap_length((p_slot.target_m - p_position_m) * (remote_stiffness_n_per_m_ * p_gain),
					order.magnitude_n);
		case PongEffectKind::NONE:
			break;
	}
	return Vec3{};
}

Vec3 HandEffects::advance(double p_dt_s, const Vec3 &p_position_m, const Vec3 &p_velocity_m_per_s,
		const StylusSample (&p_styluses)[PONG_MAX_PLAYERS]) {
	// First-order low-pass of the remote target: the owner's position arrives at frame rate
	// (and over the network), and a step in it must not become a step in the force.
	const double alpha = 1.0 - std::exp(-2.0 * std::numbers::pi * remote_cutoff_hz_ * p_dt_s);
	Vec3 total;
	for (Slot &slot : slots_) {
		if (!slot.running) {
			continue;
		}
		const bool remote = slot.order.kind == PongEffectKind::REMOTE;
		if (remote) {
			const StylusSample &owner = p_styluses[slot.order.owner];
			const double ahead = std::clamp(owner.age_s, 0.0, remote_max_extrapolation_s_);
			const Vec3 target = mirror_left_right(owner.position_m + owner.velocity_m_per_s * ahead);
			slot.target_m += (target - slot.target_m) * alpha;
		}
		const double gain = effect_gain(slot.elapsed_s, slot.order.duration_s, slot.order.ramp_s);
		const Vec3 f = force(slot, gain, p_position_m, p_velocity_m_per_s);
		if (remote) {
			total += keep_passive(slot, f, p_position_m, p_velocity_m_per_s, p_dt_s);
		} else {
			total += f;
		}
		slot.elapsed_s += p_dt_s;
		if (slot.elapsed_s >= slot.order.duration_s) {
			slot = Slot{};
		}
	}
	return total;
}

size_t HandEffects::list(PongEffectState *r_out) const {
	size_t count = 0;
	for (const Slot &slot : slots_) {
		if (slot.running && count < PONG_MAX_ACTIVE_EFFECTS) {
			r_out[count++] = PongEffectState{ slot.order.kind, slot.order.duration_s - slot.elapsed_s };
		}
	}
	return count;
}

} // namespace haptics
