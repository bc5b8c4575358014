#include "core/servo/input_vector.h"

#include <algorithm>

namespace haptics {

Vec3 input_vector(const Vec3 &p_position_m, double p_radius_m, double p_dead_zone) {
	const Vec3 raw = p_position_m / p_radius_m;
	const double magnitude = length(raw);
	if (!(magnitude > p_dead_zone) || magnitude <= 0.0) {
		return {};
	}
	const double clamped = std::min(magnitude, 1.0);
	const double rescaled = (clamped - p_dead_zone) / (1.0 - p_dead_zone);
	return raw * (rescaled / magnitude);
}

} // namespace haptics
