#pragma once

// The limits a backend's device config declares for what it cannot ask the hardware (its
// force, stiffness and reach, and its I/O rate), checked alike for every backend that has them.

#include "core/base/status.h"

namespace haptics {

struct DeviceConfigLimits {
	double max_force_n = 0.0;
	double max_continuous_force_n = 0.0;
	double max_stiffness_n_per_m = 0.0;
	double workspace_radius_m = 0.0;
	double rate_hz = 0.0;
};

// Each in (0, its bound]: 100 N, the peak force, 1e5 N/m, 1 m, 1 kHz. p_section names the
// config in the message ("evdev_device.max_force_n must be in (0, 100] (got 0)").
Status check_device_config_limits(const char *p_section, const DeviceConfigLimits &p_limits);

} // namespace haptics
