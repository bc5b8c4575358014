#include "devices/device_config_limits.h"

#include <cmath>

namespace haptics {

Status check_device_config_limits(const char *p_section, const DeviceConfigLimits &p_limits) {
	const struct {
		const char *name;
		double value;
		double max;
	} fields[] = {
		{ "max_force_n", p_limits.max_force_n, 100.0 },
		{ "max_continuous_force_n", p_limits.max_continuous_force_n, p_limits.max_force_n },
		{ "max_stiffness_n_per_m", p_limits.max_stiffness_n_per_m, 1e5 },
		{ "workspace_radius_m", p_limits.workspace_radius_m, 1.0 },
		{ "rate_hz", p_limits.rate_hz, 1000.0 },
	};
	for (const auto &field : fields) {
		if (!std::isfinite(field.value) || !(field.value > 0.0) || !(field.value <= field.max)) {
			return Status::error(std::isfinite(field.value) ? StatusCode::OUT_OF_RANGE : StatusCode::INVALID_ARGUMENT,
					"%s.%s must be in (0, %g] (got %g)", p_section, field.name, field.max, field.value);
		}
	}
	return Status::success();
}

} // namespace haptics
