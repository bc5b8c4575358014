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

// Which renderer the servo runs. Both go through the same safety stage.
enum class RenderMode : int32_t {
	// The paper's method: acceleration control, forces from the frame's contacts.
	MOVEMENT = 0,
	// Position control against the maze's walls: a finite proxy (finite_proxy.h) in the
	// geometry set with set_constraint_geometry, F = k_c (proxy - device). The game still
	// submits a frame every physics tick (contacts may be empty): it is the watchdog's
	// heartbeat, and the clock of the FRAME_RATE proxy.
	CONSTRAINT = 1,
};

enum class ProxyUpdate : int32_t {
	SERVO_RATE = 0, // The proxy moves every servo tick (1 kHz): the product.
	// The proxy moves only on ticks that pick up a new frame (50 Hz), as in the paper's
	// study; between frames it is held and the force still follows the device at the servo
	// rate.
	FRAME_RATE = 1,
};

struct ConstraintConfig {
	// k_c, N/m, [0, 5000]. Keep it at or below the device's max_stiffness_n_per_m (the
	// force is clamped by the safety stage either way).
	double stiffness_n_per_m = 300.0;
	// Radius of the proxy disc in MAZE units (the avatar's collision radius), [1e-6, 1e6].
	// Changing it re-places the proxy (see FiniteProxy::reset).
	double proxy_radius = 8.0;
	ProxyUpdate update = ProxyUpdate::SERVO_RATE;
	// Sweeps per proxy update, [1, 16]: a corner needs 2-3, a dead end 3-4.
	uint32_t max_iterations = 6;
};

struct RenderConfig {
	ForceModelConfig force_model;
	SmoothingConfig smoothing;
	SafetyConfig safety;
	TelemetryConfig telemetry;
	RenderMode render_mode = RenderMode::MOVEMENT;
	ConstraintConfig constraint;
};

static_assert(std::is_trivially_copyable_v<RenderConfig>);

} // namespace haptics
