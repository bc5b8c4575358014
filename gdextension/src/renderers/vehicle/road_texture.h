#pragma once

// The road under the steered wheels, felt at the rim, one sample a servo tick:
//
//   ripple     each wheel on a rippled surface (a kerb's ridges): A_r sin(phi),
//              dphi/dt = 2 pi min(v / spacing, MAX_RIPPLE_HZ). The phase is carried from
//              tick to tick (a change of speed bends the frequency without a jump) and starts
//              at 0 when the wheel rolls onto the ripple, so entering a kerb never steps the force.
//   roughness  each wheel on a rough surface: a uniform noise, low-passed at v / GRAIN_M Hz (a
//              rougher feel the faster it rolls) and scaled to an RMS of
//              A_n min(1, v / full_speed); bounded by 3 A_n.
//
// The wheels' textures add up. Deterministic (a xorshift generator per wheel, seeded per
// wheel at reset); no allocation.

#include "renderers/vehicle/vehicle.gen.h"

#include <array>
#include <cstdint>

namespace haptics {

class RoadTexture {
public:
	// The roughness's grain: its noise is low-passed at speed / GRAIN_M (2 cm: 250 Hz at 5 m/s,
	// capped at MAX_RIPPLE_HZ).
	static constexpr double GRAIN_M = 0.02;

	struct Sample {
		double force_n = 0.0;
		double fastest_ripple_hz = 0.0; // 0: no ripple playing.
	};

	void reset();
	// One tick of p_dt_s over the frame's wheels; p_full_speed_m_per_s: where roughness is
	// felt in full.
	Sample advance(const VehicleFrame &p_frame, double p_full_speed_m_per_s, double p_dt_s);

private:
	struct Wheel {
		double phase_rad = 0.0;
		bool on_ripple = false;
		double noise = 0.0; // The low-passed noise, in [-1, 1].
		uint32_t random = 1;
	};

	double ripple(Wheel &r_wheel, const TyreContact &p_contact, double p_dt_s, double &r_fastest_hz);
	double roughness(Wheel &r_wheel, const TyreContact &p_contact, double p_full_speed_m_per_s, double p_dt_s);

	std::array<Wheel, VEHICLE_MAX_STEERED_WHEELS> wheels_{};
};

} // namespace haptics
