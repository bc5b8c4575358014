#pragma once

// The last stage before the device, in this order (each step states why it sits there):
//   0. hold: a physical device gets zero until it is ready (homed) and the rendered force
//      is below SafetyConfig::start_force_n, so a session never begins by throwing the hand
//      (CHAI3D's "wait for small force"); the start-up ramp begins when the hold ends.
//   1. slew-rate limit on the smoothed continuous force: |dF| <= slew_rate * dt per tick,
//      so a sudden contact or a config change cannot produce a step (OpenHaptics' "impulse
//      limit"). Impacts are exempt: they are meant to be sharp and start at zero anyway.
//   2. continuous cap: a physical device's continuous force is clamped to its continuous
//      rating (motors overheat above it); only transients may reach the peak.
//   3. watchdog gain on the continuous force: when no frame has arrived for
//      watchdog_timeout_s (the game froze, a scene is loading, the engine hung) the gain
//      falls linearly to 0 over watchdog_fade_s, and rises back the same way once frames
//      return. Applied after the slew limiter so the fade time is guaranteed.
//   4. + impact transients (raw).
//   5. start-up ramp on everything: gain rises linearly 0 -> 1 over startup_ramp_s after
//      every (re)start, so opening a device or starting the servo never kicks.
//   6. non-finite guard: anything non-finite becomes zero (and is counted).
//   7. clamp to the peak force limit by scaling the whole vector, keeping its direction.
// No allocation, no branches on anything but numbers: runs inside the tick.

#include "core/base/vec3.h"
#include "core/servo/servo_config.h"

#include <cstdint>

namespace haptics {

struct SafetyResult {
	Vec3 continuous; // After slew limit, continuous cap and watchdog gain.
	Vec3 total; // What may be written to the device.
	Vec3 impact; // The transients' share of `total` (after ramp and clamp).
	double ramp_gain = 0.0;
	double watchdog_gain = 0.0;
	bool watchdog_tripped = false;
	bool clamped = false;
	bool non_finite = false;
	bool holding = false; // Zero output: waiting for the device to be ready or the force small.
};

// What the safety stage needs to know about the device.
struct SafetyDevice {
	double max_force_n = 0.0; // Peak.
	double max_continuous_force_n = 0.0; // Rating; 0: none (only the peak limit).
	bool wait_for_small_force = false; // Physical devices: hold zero at start (step 0).
};

class SafetyStage {
public:
	// The effective peak limit is the smaller of the device's and SafetyConfig::max_force_n
	// (when that is non-zero); the continuous cap likewise with max_continuous_force_n.
	// Keeps the ramp and slew state.
	void configure(const SafetyConfig &p_config, const SafetyDevice &p_device);
	void configure(const SafetyConfig &p_config, double p_device_max_force_n) {
		configure(p_config, SafetyDevice{ p_device_max_force_n, 0.0, false });
	}
	// A new rendering session: ramp from zero, slew state at zero, watchdog armed.
	void reset();

	// p_frame_age_s: servo time since the last new frame (infinity when none ever came).
	// p_device_ready: false while the device is not homed/calibrated (zero output).
	SafetyResult apply(const Vec3 &p_smoothed, const Vec3 &p_impact, double p_frame_age_s, double p_dt_s,
			bool p_device_ready = true);

	double max_force_n() const { return max_force_n_; }
	double max_continuous_force_n() const { return max_continuous_n_; }

private:
	SafetyConfig config_;
	double max_force_n_ = 0.0;
	double max_continuous_n_ = 0.0;
	bool wait_for_small_force_ = false;
	bool holding_ = false;
	Vec3 slewed_;
	double ramp_elapsed_s_ = 0.0;
	double watchdog_gain_ = 1.0;
};

// Scales p_force down to p_max_n if longer, keeping its direction; sets r_clamped.
Vec3 clamp_magnitude(const Vec3 &p_force, double p_max_n, bool &r_clamped);

} // namespace haptics
