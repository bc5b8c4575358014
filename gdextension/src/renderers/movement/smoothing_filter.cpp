#include "renderers/movement/smoothing_filter.h"

#include <cmath>
#include <numbers>

namespace haptics {

BiquadCoefficients butterworth_lowpass(double p_cutoff_hz, double p_dt_s) {
	const double k = std::tan(std::numbers::pi * p_cutoff_hz * p_dt_s);
	const double q_inv = std::numbers::sqrt2; // 1/Q with Q = 1/sqrt(2).
	const double norm = 1.0 / (1.0 + k * q_inv + k * k);
	BiquadCoefficients c;
	c.b0 = k * k * norm;
	c.b1 = 2.0 * c.b0;
	c.b2 = c.b0;
	c.a1 = 2.0 * (k * k - 1.0) * norm;
	c.a2 = (1.0 - k * q_inv + k * k) * norm;
	return c;
}

void SmoothingFilter::configure(const SmoothingConfig &p_config, double p_dt_s) {
	enabled_ = p_config.enabled;
	if (enabled_) {
		coefficients_ = butterworth_lowpass(p_config.cutoff_hz, p_dt_s);
	} else {
		coefficients_ = BiquadCoefficients{};
	}
	reset(last_output_);
}

void SmoothingFilter::reset(const Vec3 &p_value) {
	const BiquadCoefficients &c = coefficients_;
	// Steady state of the transposed direct form II with x = y = p_value.
	s2_ = p_value * (c.b2 - c.a2);
	s1_ = p_value * (c.b1 - c.a1) + s2_;
	last_output_ = p_value;
}

Vec3 SmoothingFilter::process(const Vec3 &p_input) {
	if (!enabled_) {
		last_output_ = p_input;
		return p_input;
	}
	const BiquadCoefficients &c = coefficients_;
	const Vec3 output = p_input * c.b0 + s1_;
	s1_ = p_input * c.b1 - output * c.a1 + s2_;
	s2_ = p_input * c.b2 - output * c.a2;
	last_output_ = output;
	return output;
}

} // namespace haptics
