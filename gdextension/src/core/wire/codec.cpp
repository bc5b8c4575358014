#include "core/wire/codec.h"

namespace haptics::wire_detail {

void check_number(WireReader &r_reader, const FieldSpec &p_spec, double p_value) {
	if (p_spec.finite && !std::isfinite(p_value)) {
		r_reader.fail(StatusCode::INVALID_ARGUMENT, "not finite (%g)", p_value);
	} else if (p_spec.zero_means != nullptr && p_value == 0.0) {
		return;
	} else if ((p_value < p_spec.min || p_value > p_spec.max) && p_spec.zero_means != nullptr) {
		r_reader.fail(StatusCode::OUT_OF_RANGE, "%g is neither 0 (%s) nor in [%g, %g]", p_value, p_spec.zero_means,
				p_spec.min, p_spec.max);
	} else if (p_value < p_spec.min || p_value > p_spec.max) {
		r_reader.fail(StatusCode::OUT_OF_RANGE, "%g is outside [%g, %g]", p_value, p_spec.min, p_spec.max);
	}
}

void check_vector(WireReader &r_reader, const FieldSpec &p_spec, const Vec3 &p_value) {
	const bool finite = std::isfinite(p_value.x) && std::isfinite(p_value.y) && std::isfinite(p_value.z);
	const double length = std::sqrt(p_value.x * p_value.x + p_value.y * p_value.y + p_value.z * p_value.z);
	if (p_spec.finite && !finite) {
		r_reader.fail(StatusCode::INVALID_ARGUMENT, "not finite (%g, %g, %g)", p_value.x, p_value.y, p_value.z);
	} else if (p_spec.nonzero && !(length > 1e-9)) {
		r_reader.fail(StatusCode::INVALID_ARGUMENT, "zero length: a direction is needed");
	} else if (length > p_spec.max) {
		r_reader.fail(StatusCode::OUT_OF_RANGE, "length %g is above %g", length, p_spec.max);
	}
}

} // namespace haptics::wire_detail
