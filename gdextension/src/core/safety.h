#pragma once

// The last stage before the device, in this order (each step states why it sits there):
//   1. slew-rate limit on the smoothed continuous force: |dF| <= slew_rate * dt per tick,
//      so a sudden contact or a config change cannot produce a step (OpenHaptics' "impulse
//      limit"). Impacts are exempt: they are meant to be sharp and start at zero anyway.
//   2. watchdog gain on the continuous force: when no frame has arrived for
//      watchdog_timeout_s (the game froze, a scene is loading, the engine hung) the gain
//      falls linearly to 0 over watchdog_fade_s, and rises back the same way once frames
//      return. Applied after the slew limiter so the fade time is guaranteed.
//   3. + impact transients (raw).
//   4. start-up ramp on everything: gain rises linearly 0 -> 1 over startup_ramp_s after
//      every (re)start, so opening a device or starting the servo never kicks.
//   5. non-finite guard: anything non-finite becomes zero (and is counted).
//   6. clamp to the force limit by scaling the whole vector, keeping its direction.
// No allocation, no branches on anything but numbers: runs inside the tick.

#include "core/config.h"
#include "core/vec3.h"

#include <cstdint>

namespace haptics {

struct SafetyResult {
	Vec3 continuous; // After slew limit and watchdog gain.
	Vec3 total; // What may be written to the device.
	double ramp_gain = 0.0;
	double watchdog_gain = 0.0;
	bool watchdog_tripped = false;
	bool clamped = false;
	bool non_finite = false;
};

class SafetyStage {
public:
	// p_device_max_force_n: the device's own limit; the effective limit is the smaller of it
	// and SafetyConfig::max_force_n (when that is non-zero). Keeps the ramp and slew state.
	void configure(const SafetyConfig &p_config, double p_device_max_force_n);
	// A new rendering session: ramp from zero, slew state at zero, watchdog armed.
	void reset();

	// p_frame_age_s: servo time since the last new frame (infinity when none ever came).
	SafetyResult apply(const Vec3 &p_smoothed, const Vec3 &p_impact, double p_frame_age_s, double p_dt_s);

	double max_force_n() const { return max_force_n_; }

private:
	SafetyConfig config_;
	double max_force_n_ = 0.0;
	Vec3 slewed_;
	double ramp_elapsed_s_ = 0.0;
	double watchdog_gain_ = 1.0;
};

// Scales p_force down to p_max_n if longer, keeping its direction; sets r_clamped.
Vec3 clamp_magnitude(const Vec3 &p_force, double p_max_n, bool &r_clamped);

} // namespace haptics
