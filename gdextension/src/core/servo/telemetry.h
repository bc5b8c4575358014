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
//    7..21   parts        the active renderer's force components (ForceComponents::parts),
//                         three columns each, in the order of its force names, N (the
//                         movement renderer's normal, friction, weight, drag, inertia; the
//                         constraint renderer's wall force in the first; Pong's contact,
//                         spin, effects in the first three)
//   22..24   smoothed     continuous sum after smoothing, slew limit and watchdog, N
//   25..27   impact       sum of impact transients, raw, N
//   28..30   total        force written to the device, N
//   31       flags        bit field stored as a float (exact up to 2^24): TelemetryFlag and
//                         the active renderer's own flags (RendererInfo::telemetry_flags)
// The raw continuous sum is not stored: it is the sum of columns 7..21.

#include "core/base/vec3.h"
#include "core/render/force_components.h"
#include "core/render/renderer_info.h"

#include "core/servo/servo.gen.h"

#include <cstddef>
#include <cstdint>
#include <span>

namespace haptics {

inline constexpr size_t TELEMETRY_STRIDE = 32;

enum TelemetryColumn : size_t {
	TELEMETRY_TIME = 0,
	TELEMETRY_INPUT = 1,
	TELEMETRY_POSITION = 4,
	TELEMETRY_PARTS = 7,
	TELEMETRY_SMOOTHED = TELEMETRY_PARTS + 3 * MAX_FORCE_PARTS,
	TELEMETRY_IMPACT = 25,
	TELEMETRY_TOTAL = 28,
	TELEMETRY_FLAGS = 31,
};
static_assert(TELEMETRY_SMOOTHED == 22);

// The first of the three columns of force part p_part.
constexpr size_t telemetry_part_column(size_t p_part) {
	return TELEMETRY_PARTS + 3 * p_part;
}

// The servo's own flags (TELEMETRY_FLAG_*, servo.schema.toml); renderers raise theirs from
// FIRST_RENDERER_FLAG_BIT up.
static_assert(TELEMETRY_FLAG_NEW_FRAME < (1u << FIRST_RENDERER_FLAG_BIT));

// The servo's own flag bits.
std::span<const uint32_t> servo_telemetry_flags();

struct TelemetrySample {
	float values[TELEMETRY_STRIDE] = {};
};

TelemetrySample make_telemetry_sample(double p_time_s, const Vec3 &p_input, const Vec3 &p_position,
		const ForceComponents &p_forces, uint32_t p_flags);

} // namespace haptics
