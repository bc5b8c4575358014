#pragma once

// The rates the servo runs at: the thread's (start) and a manual step's period (step).

#include "core/base/status.h"
#include "core/servo/servo.gen.h"

namespace haptics {

// MIN_RATE_HZ, MAX_RATE_HZ, DEFAULT_RATE_HZ: servo.schema.toml.

// Servo rate in Hz, [MIN_RATE_HZ, MAX_RATE_HZ].
Status validate_rate(double p_rate_hz);
// Manual step period in s, [1 / MAX_RATE_HZ, 1 / MIN_RATE_HZ].
Status validate_step_dt(double p_dt_s);

} // namespace haptics
