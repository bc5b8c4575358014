#include "pong/hand_effects.h"

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
}

void HandEffects::clear() {
	for (Slot &slot : slots_) {
		slot = Slot{};
	}
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
		const Vec3 (&p_styluses)[PONG_MAX_PLAYERS]) {
	// First-order low-pass of the remote target: the owner's position arrives at frame rate
	// (and over the network), and a step in it must not become a step in the force.
	const double alpha = 1.0 - std::exp(-2.0 * std::numbers::pi * remote_cutoff_hz_ * p_dt_s);
	Vec3 total;
	for (Slot &slot : slots_) {
		if (!slot.running) {
			continue;
		}
		if (slot.order.kind == PongEffectKind::REMOTE) {
			const Vec3 target = mirror_left_right(p_styluses[slot.order.owner]);
			slot.target_m += (target - slot.target_m) * alpha;
		}
		const double gain = effect_gain(slot.elapsed_s, slot.order.duration_s, slot.order.ramp_s);
		total += force(slot, gain, p_position_m, p_velocity_m_per_s);
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
