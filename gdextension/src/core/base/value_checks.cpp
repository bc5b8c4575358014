#include "core/base/value_checks.h"

#include <cmath>

namespace haptics {

namespace {

// Normals shorter than this carry no direction.
constexpr double MIN_DIRECTION_LENGTH = 1e-6;

} // namespace

Status check_range(const char *p_name, double p_value, double p_min, double p_max) {
	if (!std::isfinite(p_value)) {
		return Status::error(StatusCode::INVALID_ARGUMENT, "%s: not finite (%g)", p_name, p_value);
	}
	if (p_value < p_min || p_value > p_max) {
		return Status::error(StatusCode::OUT_OF_RANGE, "%s must be in [%g, %g] (got %g)", p_name, p_min, p_max, p_value);
	}
	return Status::success();
}

Status check_vector(const char *p_name, const Vec3 &p_value, bool p_nonzero, double p_max_length) {
	if (!is_finite(p_value)) {
		return Status::error(StatusCode::INVALID_ARGUMENT, "%s: not finite (%g, %g, %g)", p_name, p_value.x, p_value.y,
				p_value.z);
	}
	const double len = length(p_value);
	if (p_nonzero && len < MIN_DIRECTION_LENGTH) {
		return Status::error(StatusCode::INVALID_ARGUMENT, "%s: zero length, a direction is needed", p_name);
	}
	if (len > p_max_length) {
		return Status::error(StatusCode::OUT_OF_RANGE, "%s: length must be <= %g (got %g)", p_name, p_max_length, len);
	}
	return Status::success();
}

} // namespace haptics
