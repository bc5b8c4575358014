#pragma once

// Impact transients: decaying sinusoids (Okamura & al.'s "reality-based" vibration model,
// the paper's ref. [7]) rendered raw on top of the smoothed continuous force.
//
//   s(t) = A(v) e^(-t/tau) sin(2 pi f t) * direction,   A(v) = min(scale * gain * v, max_amplitude)
//
// t is counted in servo ticks from when the servo took the event off the queue: the k-th
// tick after that (k = 1, 2, ...) renders s(k dt). Starting at sin(0) = 0 means an impact
// never jumps the output, however large A is. Concurrent transients add up. A transient is
// dropped once its envelope falls below EXPIRY_N.
//
// Fixed capacity, no allocation. When the bank is full a new event replaces the weakest
// active transient if the new one is stronger (otherwise it is discarded); either way one
// drop is counted. Overflow is never fatal.

#include "core/base/vec3.h"
#include "core/render/frame.h"

#include <cstddef>
#include <cstdint>

namespace haptics {

class TransientBank {
public:
	static constexpr size_t CAPACITY = 16;
	static constexpr double EXPIRY_N = 1e-4;

	// p_event must be valid (validate_impact); p_default is used when the event asks for
	// the default material; p_gain_scale (the force scale) multiplies its gain before the
	// cap. Returns false when a drop was counted.
	bool add(const ImpactEvent &p_event, const ImpactMaterial &p_default, double p_max_amplitude_n,
			double p_gain_scale = 1.0);
	// Advances every transient by p_dt_s, then returns the sum of their values.
	Vec3 advance(double p_dt_s);
	void clear();

	size_t active_count() const { return count_; }
	uint64_t drops() const { return drops_; }

private:
	struct Transient {
		Vec3 direction; // Unit.
		double amplitude_n = 0.0;
		double angular_frequency = 0.0; // rad/s
		double decay_s = 1.0;
		double age_s = 0.0;
	};

	double envelope(const Transient &p_transient) const;

	Transient transients_[CAPACITY];
	size_t count_ = 0;
	uint64_t drops_ = 0;
};

} // namespace haptics
