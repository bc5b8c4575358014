#include "core/servo/transients.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace haptics {

double TransientBank::envelope(const Transient &p_transient) const {
	return p_transient.amplitude_n * std::exp(-p_transient.age_s / p_transient.decay_s);
}

bool TransientBank::add(const ImpactEvent &p_event, const ImpactMaterial &p_default, double p_max_amplitude_n,
		double p_gain_scale) {
	const ImpactMaterial &material = p_event.material.value_or(p_default);
	Transient transient;
	transient.direction = normalized_or_zero(p_event.direction);
	transient.amplitude_n = std::min(p_gain_scale * material.gain_n_s_per_m * p_event.speed_m_per_s, p_max_amplitude_n);
	transient.angular_frequency = 2.0 * std::numbers::pi * material.frequency_hz;
	transient.decay_s = material.decay_s;
	if (!(transient.amplitude_n > EXPIRY_N)) {
		return true; // Too weak to feel: nothing to render, nothing dropped.
	}
	if (count_ < CAPACITY) {
		transients_[count_++] = transient;
		return true;
	}
	++drops_;
	size_t weakest = 0;
	double weakest_envelope = envelope(transients_[0]);
	for (size_t t = 1; t < count_; ++t) {
		const double e = envelope(transients_[t]);
		if (e < weakest_envelope) {
			weakest = t;
			weakest_envelope = e;
		}
	}
	if (transient.amplitude_n > weakest_envelope) {
		transients_[weakest] = transient;
	}
	return false;
}

Vec3 TransientBank::advance(double p_dt_s) {
	Vec3 sum;
	size_t t = 0;
	while (t < count_) {
		Transient &transient = transients_[t];
		transient.age_s += p_dt_s;
		const double env = envelope(transient);
		if (env < EXPIRY_N) {
			transients_[t] = transients_[--count_]; // Order does not matter: values add up.
			continue;
		}
		sum += transient.direction * (env * std::sin(transient.angular_frequency * transient.age_s));
		++t;
	}
	return sum;
}

void TransientBank::clear() {
	count_ = 0;
}

} // namespace haptics
