#pragma once

// Tunable parameters of the renderer, grouped as the game configures them. Each group is
// validated as a whole (validation.h) and handed to the servo thread through a lock-free
// snapshot, so it may be changed while rendering; a rejected group leaves the previous one
// in force. Ranges are inclusive unless stated.

#include "core/frame.h"

#include <cstdint>
#include <type_traits>

namespace haptics {

struct ForceModelConfig {
	// Fraction of the workspace radius around the centre that gives no input, [0, 0.5].
	// Outside it the input is rescaled so it grows continuously from 0 at the edge.
	double dead_zone = 0.05;
	// "g" of W = m g (n.d) d, in N/kg, [0, 100]. Not Earth's 9.81: it is the gain from the
	// game's masses to felt weight, and 9.81 would saturate a 3.3 N device with a 1 kg crate.
	double gravity = 1.0;
	// Radius that maps to |i| = 1, in metres; 0 means the device's workspace radius, else
	// [0.001, 1].
	double input_radius_m = 0.0;
	ContactMaterial default_contact; // For contacts with use_default_material.
	ImpactMaterial default_impact; // For impacts with use_default_material.
};

enum class SmoothingType : int32_t {
	OFF = 0, // The continuous sum goes straight through (the 50 Hz staircase is felt).
	BUTTERWORTH2 = 1, // See smoothing_filter.h for why.
};

struct SmoothingConfig {
	SmoothingType type = SmoothingType::BUTTERWORTH2;
	double cutoff_hz = 13.0; // Hz, [0.5, 60]; see smoothing_filter.h for the trade-off.
};

struct SafetyConfig {
	// Output limit in N, [0, 100]; 0 means the device's own limit, and a larger value is
	// still capped by the device's limit.
	double max_force_n = 0.0;
	// Cap on an impact's amplitude A(v), N, [0, 100].
	double max_impact_force_n = 3.0;
	// Limit on how fast the continuous force may change, N/s; 0 = off, else [1, 1e6].
	double slew_rate_n_per_s = 200.0;
	// Output gain ramps linearly 0 -> 1 over this time when rendering (re)starts, s, [0, 5].
	double startup_ramp_s = 0.3;
	// No new frame for this long trips the watchdog, s, [0.005, 10].
	double watchdog_timeout_s = 0.1;
	// Once tripped, the continuous force fades linearly to zero over this time, and fades
	// back in over the same time when frames return, s, [0, 0.05].
	double watchdog_fade_s = 0.04;
};

struct TelemetryConfig {
	// One sample every `decimation` ticks, [1, 1000]; 1 keeps every tick.
	uint32_t decimation = 1;
	bool enabled = true;
};

struct RenderConfig {
	ForceModelConfig force_model;
	SmoothingConfig smoothing;
	SafetyConfig safety;
	TelemetryConfig telemetry;
};

static_assert(std::is_trivially_copyable_v<RenderConfig>);

} // namespace haptics
