#include "renderers/vehicle/brush_tyre.h"

#include <algorithm>
#include <cmath>

namespace haptics {

TyreForces brush_tyre_forces(const BrushTyre &p_tyre, double p_load_n, double p_slip_angle_rad, double p_grip,
		bool p_rolling_backward) {
	TyreForces out;
	const double friction_n = p_grip * p_load_n; // mu F_z
	if (!(friction_n > 0.0)) {
		return out; // No load or no grip: nothing to push on.
	}
	const double theta = p_tyre.cornering_coefficient_per_rad / (3.0 * p_grip);
	const double lambda = theta * std::tan(p_slip_angle_rad);
	const double size = std::abs(lambda);
	out.slide_fraction = size;
	if (size < 1.0) {
		const double rest = 1.0 - size;
		out.lateral_force_n = friction_n * lambda * (3.0 - 3.0 * size + lambda * lambda);
		out.self_aligning_nm = -friction_n * p_tyre.contact_half_length_m * lambda * rest * rest * rest;
	} else {
		out.lateral_force_n = std::copysign(friction_n, lambda);
		out.self_aligning_nm = 0.0;
	}
	const double trail_sign = p_rolling_backward ? -1.0 : 1.0;
	out.kingpin_torque_nm = out.self_aligning_nm - trail_sign * p_tyre.mechanical_trail_m * out.lateral_force_n;
	return out;
}

double brush_peak_slide_fraction(const BrushTyre &p_tyre) {
	const double a = p_tyre.contact_half_length_m;
	return std::min(1.0, (a + 3.0 * p_tyre.mechanical_trail_m) / (4.0 * a));
}

double brush_peak_torque_per_load(const BrushTyre &p_tyre) {
	const double lambda = brush_peak_slide_fraction(p_tyre);
	const double rest = 1.0 - lambda;
	return p_tyre.contact_half_length_m * lambda * rest * rest * rest +
			3.0 * p_tyre.mechanical_trail_m * lambda * (1.0 - lambda + lambda * lambda / 3.0);
}

} // namespace haptics
