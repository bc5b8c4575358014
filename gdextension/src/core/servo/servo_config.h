#pragma once

// The servo's own settings, whatever renders: how the device's position becomes the input
// vector, the impacts' default material, the safety stage, the plane hold, telemetry, and
// which renderer runs. Each renderer's settings are its own (its Config, system/render_config.h
// joins them). Validated whole (system/config_table.h) and handed to the servo thread through
// a lock-free snapshot, so they may change while rendering; rejected settings leave the
// previous ones in force. Each field's range, unit and the key the game spells it with are in
// its row of the field table (servo_config_fields.cpp), not here.

#include "core/render/frame.h"

#include <cstdint>
#include <type_traits>

namespace haptics {

// Section "force_model" of the game's configuration, with the movement renderer's contact
// law: the input vector is every renderer's input.
struct InputConfig {
	// Fraction of the workspace radius around the centre that gives no input. Outside it the
	// input is rescaled so it grows continuously from 0 at the edge.
	double dead_zone = 0.05;
	// Radius that maps to |i| = 1; 0 means the device's workspace radius.
	double input_radius_m = 0.0;
};

struct SafetyConfig {
	// The player's strength preference: a gain on everything rendered, every renderer's
	// output (each component, so what the HUD shows is what is felt) and each impact's
	// amplitude before its cap. Applied before the slew limit, so changing it while
	// rendering never kicks.
	double force_scale = 1.0;
	// Output limit; 0 means the device's own limit, and a larger value is still capped by it.
	double max_force_n = 0.0;
	double max_impact_force_n = 3.0; // Cap on an impact's amplitude A(v).
	// Cap on the continuous force; 0 means the physical device's continuous rating (motors
	// overheat above it; a simulation has none). Transients may still reach the peak limit.
	double max_continuous_force_n = 0.0;
	// A physical device's session starts only once the rendered force is at most this
	// (and the device is ready): opening a device inside a wall never throws the hand.
	double start_force_n = 0.5;
	double slew_rate_n_per_s = 200.0; // How fast the continuous force may change; 0 = off.
	// Output gain ramps linearly 0 -> 1 over this time when rendering (re)starts.
	double startup_ramp_s = 0.3;
	double watchdog_timeout_s = 0.1; // No new frame for this long trips the watchdog.
	// Once tripped, the continuous force fades linearly to zero over this time, and fades
	// back in over the same time when frames return.
	double watchdog_fade_s = 0.04;
};

// 3-DOF devices (Falcon, Touch, the simulated stylus) in a 2D game: the depth axis z is held
// at the workspace centre by a spring-damper, F_z = -k z - b v_z, so the stylus moves in the
// game plane (the movement-based paper's Omni moved in its x-y plane). Planar renderers
// only (Renderer::planar: the movement and constraint renderers); 0 stiffness turns it off.
struct PlaneHoldConfig {
	double stiffness_n_per_m = 200.0;
	double damping_n_s_per_m = 1.0;
};

struct TelemetryConfig {
	uint32_t decimation = 1; // One sample every `decimation` ticks; 1 keeps every tick.
	bool enabled = true;
};

struct ServoConfig {
	InputConfig input;
	ImpactMaterial default_impact; // For impacts without a material ("force_model" too).
	SafetyConfig safety;
	PlaneHoldConfig plane_hold;
	TelemetryConfig telemetry;
	// The renderer that runs: its index in the list the pipeline was given (the engine's
	// renderer table, whose RenderMode names the values). Switching starts it from rest.
	int32_t render_mode = 0;
};

static_assert(std::is_trivially_copyable_v<ServoConfig>);

} // namespace haptics
