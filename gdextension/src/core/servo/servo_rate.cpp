#include "core/servo/servo_rate.h"

#include "core/base/value_checks.h"

namespace haptics {

Status validate_rate(double p_rate_hz) {
	return check_range("rate_hz", p_rate_hz, MIN_RATE_HZ, MAX_RATE_HZ);
}

Status validate_step_dt(double p_dt_s) {
	return check_range("dt", p_dt_s, 1.0 / MAX_RATE_HZ, 1.0 / MIN_RATE_HZ);
}

} // namespace haptics
