#pragma once

// What the servo publishes to the game after every tick (one lock-free snapshot). A
// renderer's own state (the maze's proxy, Pong's ball) is on its own channels.

#include "core/base/vec3.h"
#include "core/render/force_components.h"

#include <cstdint>

namespace haptics {

struct ServoOutput {
	double time_s = 0.0; // Servo time since the session started.
	uint64_t tick = 0;
	Vec3 input; // Input vector i.
	Vec3 position_m; // Device position.
	uint32_t buttons = 0;
	uint32_t flags = 0; // TelemetryFlag bits of this tick.
	ForceComponents forces;
	// Since the game's latest heartbeat: a frame, or the active renderer's own input
	// (Renderer::heard_from_game). -1 before any.
	double frame_age_s = -1.0;
	double ramp_gain = 0.0;
	double watchdog_gain = 0.0;
	uint64_t frames_received = 0;
	uint64_t bank_drops = 0; // Transients dropped because the bank was full.
	uint64_t telemetry_drops = 0;
	uint64_t clamped_ticks = 0;
	uint64_t non_finite_ticks = 0;
	int32_t render_mode = 0; // ServoConfig::render_mode of this tick.
};

} // namespace haptics
