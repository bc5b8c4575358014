#pragma once

// What the servo publishes to the game after every tick (one lock-free snapshot).

#include "core/config.h"
#include "core/force_model.h"
#include "core/vec2.h"
#include "core/vec3.h"

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
	// Since the game's latest heartbeat: a frame, or the PONG renderer's input. -1 before any.
	double frame_age_s = -1.0;
	double ramp_gain = 0.0;
	double watchdog_gain = 0.0;
	uint64_t frames_received = 0;
	uint64_t bank_drops = 0; // Transients dropped because the bank was full.
	uint64_t telemetry_drops = 0;
	uint64_t clamped_ticks = 0;
	uint64_t non_finite_ticks = 0;
	RenderMode render_mode = RenderMode::MOVEMENT;
	// Constraint renderer, maze units; filled while it is the active renderer. Until the
	// proxy is placed proxy_maze is the goal, i.e. the device mapped into the maze.
	Vec2 proxy_maze;
	Vec2 goal_maze;
	uint32_t proxy_constraints = 0; // Walls holding the proxy: 0 free, 1 sliding, 2+ stopped.
	bool proxy_placed = false;
	uint64_t proxy_updates = 0; // Proxy updates this session (1 per tick, or 1 per frame).
	// The walls the servo holds, whatever the render mode: how many geometries it has picked
	// up since the engine was made (a set_constraint_geometry has taken effect once this
	// moves), and their count.
	uint64_t geometry_generation = 0;
	uint32_t geometry_segments = 0;
};

} // namespace haptics
