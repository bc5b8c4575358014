#pragma once

// The rates the servo runs at: the thread's (start) and a manual step's period (step).

#include "core/base/status.h"

namespace haptics {

inline constexpr double MIN_RATE_HZ = 250.0;
inline constexpr double MAX_RATE_HZ = 4000.0;
inline constexpr double DEFAULT_RATE_HZ = 1000.0;

// Servo rate in Hz, [MIN_RATE_HZ, MAX_RATE_HZ].
Status validate_rate(double p_rate_hz);
// Manual step period in s, [1 / MAX_RATE_HZ, 1 / MIN_RATE_HZ].
Status validate_step_dt(double p_dt_s);

} // namespace haptics
