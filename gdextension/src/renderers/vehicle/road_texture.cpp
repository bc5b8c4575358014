#include "renderers/vehicle/road_texture.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace haptics {

namespace {

constexpr double TWO_PI = 2.0 * std::numbers::pi;
// The roughness is bounded by this many RMS (a uniform noise low-passed is nearly Gaussian).
constexpr double MAX_CREST = 3.0;

// xorshift32 (Marsaglia 2003): uniform in [-1, 1).
double next_uniform(uint32_t &r_state) {
	uint32_t x = r_state;
	x ^= x << 13;
	x ^= x >> 17;
	x ^= x << 5;
	r_state = x;
	return static_cast<double>(x) / 2147483648.0 - 1.0;
}

} // namespace

void RoadTexture::reset() {
	for (size_t w = 0; w < wheels_.size(); ++w) {
		wheels_[w] = Wheel{};
		wheels_[w].random = 0x9E3779B9u * static_cast<uint32_t>(w + 1); // Non-zero, one a wheel.
	}
}

double RoadTexture::ripple(Wheel &r_wheel, const TyreContact &p_contact, double p_dt_s, double &r_fastest_hz) {
	const bool on = p_contact.in_contact && p_contact.ripple_spacing_m > 0.0 && p_contact.ripple_n > 0.0 &&
			p_contact.speed_m_per_s > 0.0;
	if (!on) {
		r_wheel.on_ripple = false;
		return 0.0;
	}
	if (!r_wheel.on_ripple) {
		r_wheel.on_ripple = true;
		r_wheel.phase_rad = 0.0; // Rolling onto it: start at sin(0), no step.
	}
	const double hz = std::min(p_contact.speed_m_per_s / p_contact.ripple_spacing_m, MAX_RIPPLE_HZ);
	r_fastest_hz = std::max(r_fastest_hz, hz);
	r_wheel.phase_rad = std::fmod(r_wheel.phase_rad + TWO_PI * hz * p_dt_s, TWO_PI);
	return p_contact.ripple_n * std::sin(r_wheel.phase_rad);
}

double RoadTexture::roughness(Wheel &r_wheel, const TyreContact &p_contact, double p_full_speed_m_per_s, double p_dt_s) {
	const double uniform = next_uniform(r_wheel.random); // Drawn every tick: the sequence is the tick's.
	if (!p_contact.in_contact || !(p_contact.roughness_n > 0.0) || !(p_contact.speed_m_per_s > 0.0)) {
		r_wheel.noise = 0.0;
		return 0.0;
	}
	const double cutoff_hz = std::min(p_contact.speed_m_per_s / GRAIN_M, MAX_RIPPLE_HZ);
	const double k = 1.0 - std::exp(-TWO_PI * cutoff_hz * p_dt_s);
	r_wheel.noise += k * (uniform - r_wheel.noise);
	// A one-pole low-pass of a uniform noise (variance 1/3) has variance k / (3 (2 - k)).
	const double rms = std::sqrt(k / (3.0 * (2.0 - k)));
	const double unit = std::clamp(r_wheel.noise / rms, -MAX_CREST, MAX_CREST);
	const double strength = std::min(1.0, p_contact.speed_m_per_s / p_full_speed_m_per_s);
	return p_contact.roughness_n * strength * unit;
}

RoadTexture::Sample RoadTexture::advance(const VehicleFrame &p_frame, double p_full_speed_m_per_s, double p_dt_s) {
	Sample out;
	for (size_t w = 0; w < p_frame.wheels.size(); ++w) {
		const TyreContact &contact = p_frame.wheels[w];
		out.force_n += ripple(wheels_[w], contact, p_dt_s, out.fastest_ripple_hz);
		out.force_n += roughness(wheels_[w], contact, p_full_speed_m_per_s, p_dt_s);
	}
	for (size_t w = p_frame.wheels.size(); w < wheels_.size(); ++w) {
		wheels_[w].on_ripple = false;
		wheels_[w].noise = 0.0;
	}
	return out;
}

} // namespace haptics
