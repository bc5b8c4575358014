#pragma once

// Telemetry: one fixed-layout sample of TELEMETRY_STRIDE floats per servo tick (or every
// `decimation` ticks), pushed by the servo into an SPSC ring and drained by the game into a
// flat float array (a PackedFloat32Array in GDScript). Floats because that is what the game
// stores and plots; the time column loses millisecond resolution only after ~4.6 hours.
//
// Layout of one sample (index: meaning), device space (x right, y up, z toward the user):
//    0       t            servo time since rendering started, s
//    1..3    input        input vector i, dimensionless
//    4..6    position     device position, m
//    7..9    normal       F_n, N (in RenderMode::CONSTRAINT: k_c (proxy - device); in
//                         RenderMode::PONG: the paddle's contact force)
//   10..12   friction     F_f, N (PONG: the spinning ball's drag on the paddle)
//   13..15   weight       W, N (PONG: the effects: recoil, hit, slow, heavy, remote)
//   16..18   drag         water drag, N
//   19..21   inertia      water inertia, N
//   22..24   smoothed     continuous sum after smoothing, slew limit and watchdog, N
//   25..27   impact       sum of impact transients, raw, N
//   28..30   total        force written to the device, N
//   31       flags        bit field stored as a float (exact up to 2^24): TelemetryFlag
// The raw continuous sum is not stored: it is the sum of columns 7..21.

#include "core/force_model.h"
#include "core/vec3.h"

#include <cstddef>
#include <cstdint>

namespace haptics {

inline constexpr size_t TELEMETRY_STRIDE = 32;

enum TelemetryColumn : size_t {
	TELEMETRY_TIME = 0,
	TELEMETRY_INPUT = 1,
	TELEMETRY_POSITION = 4,
	TELEMETRY_NORMAL = 7,
	TELEMETRY_FRICTION = 10,
	TELEMETRY_WEIGHT = 13,
	TELEMETRY_DRAG = 16,
	TELEMETRY_INERTIA = 19,
	TELEMETRY_SMOOTHED = 22,
	TELEMETRY_IMPACT = 25,
	TELEMETRY_TOTAL = 28,
	TELEMETRY_FLAGS = 31,
};

enum TelemetryFlag : uint32_t {
	TELEMETRY_FLAG_CONTACT = 1u << 0, // The frame has at least one contact.
	TELEMETRY_FLAG_IN_WATER = 1u << 1,
	TELEMETRY_FLAG_WATCHDOG = 1u << 2, // Watchdog tripped (frames stale).
	TELEMETRY_FLAG_CLAMPED = 1u << 3, // Output scaled down to the force limit.
	TELEMETRY_FLAG_RAMPING = 1u << 4, // Start-up ramp below 1.
	TELEMETRY_FLAG_NON_FINITE = 1u << 5, // A non-finite value was replaced by zero.
	TELEMETRY_FLAG_NEW_FRAME = 1u << 6, // This tick picked up a new frame.
	TELEMETRY_FLAG_CONSTRAINT_MODE = 1u << 7, // RenderMode::CONSTRAINT (force in `normal`).
	TELEMETRY_FLAG_PROXY_CONTACT = 1u << 8, // The proxy is held by at least one wall.
	TELEMETRY_FLAG_PONG_MODE = 1u << 9, // RenderMode::PONG (see the columns above).
	TELEMETRY_FLAG_PADDLE_CONTACT = 1u << 10, // The device player's paddle touches the ball.
};

struct TelemetrySample {
	float values[TELEMETRY_STRIDE] = {};
};

TelemetrySample make_telemetry_sample(double p_time_s, const Vec3 &p_input, const Vec3 &p_position,
		const ForceComponents &p_forces, uint32_t p_flags);

} // namespace haptics
