#include "core/config/config_field.h"

#include <cmath>

namespace haptics {

Status check_config_value(const ConfigField &p_field, double p_value) {
	const char *section = p_field.section;
	const char *key = p_field.key;
	if (!std::isfinite(p_value)) {
		return Status::error(StatusCode::INVALID_ARGUMENT, "%s.%s: not finite (%g)", section, key, p_value);
	}
	switch (p_field.kind) {
		case FieldKind::NUMBER:
			if (p_field.zero_means && p_value == 0.0) {
				return Status::success();
			}
			break;
		case FieldKind::COUNT:
			if (p_value != std::floor(p_value)) {
				return Status::error(StatusCode::INVALID_ARGUMENT, "%s.%s must be a whole number (got %g)", section, key,
						p_value);
			}
			break;
		case FieldKind::FLAG:
			if (p_value != 0.0 && p_value != 1.0) {
				return Status::error(StatusCode::INVALID_ARGUMENT, "%s.%s must be true or false (got %g)", section, key,
						p_value);
			}
			return Status::success();
		case FieldKind::CHOICE:
			if (p_value != std::floor(p_value) || p_value < 0.0 || p_value >= static_cast<double>(p_field.choices.size())) {
				return Status::error(StatusCode::INVALID_ARGUMENT, "%s.%s: unknown value %g", section, key, p_value);
			}
			return Status::success();
	}
	if (p_value < p_field.min || p_value > p_field.max) {
		if (p_field.zero_means) {
			return Status::error(StatusCode::OUT_OF_RANGE, "%s.%s must be 0 (%s) or in [%g, %g] (got %g)", section, key,
					p_field.zero_means, p_field.min, p_field.max, p_value);
		}
		return Status::error(StatusCode::OUT_OF_RANGE, "%s.%s must be in [%g, %g] (got %g)", section, key, p_field.min,
				p_field.max, p_value);
	}
	return Status::success();
}

} // namespace haptics
