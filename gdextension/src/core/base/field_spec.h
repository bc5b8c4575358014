#pragma once

// What the schema says about one field of a value (tools/schema, docs/values.md): its name
// as GDScript spells it, how it travels and the limits a decoded or submitted value must
// keep. Each generated struct lists its fields with these in its visit() (*.gen.h), and the
// codec (codec.h) and the checker (field_checks.h) walk them, so a field's limits are
// written once, in its schema.

#include <cstdint>
#include <limits>

namespace haptics {

enum class Wire : uint8_t {
	PLAIN, // The member's own width: doubles as f64, Vec2/Vec3 as f64 components.
	F32, // Floats and vectors as f32 (network messages; C++ keeps doubles).
	// A device-space Vec3 that travels as a 2D game vector, (x, -y) with z dropped, or in its
	// value's 3D form as (x, y, z) (GameSpace, core/base/coordinates.h).
	GAME_VEC2,
};

struct FieldSpec {
	const char *name = "";
	Wire wire = Wire::PLAIN;
	double min = -std::numeric_limits<double>::infinity();
	double max = std::numeric_limits<double>::infinity();
	uint32_t max_count = 0; // Arrays: items; strings: bytes.
	bool nonzero = false; // Vectors: must carry a direction.
	bool finite = true; // Floats and vectors: NaN and infinities are refused.
	// Numbers: when set, 0 is accepted besides [min, max], and this says what it means.
	const char *zero_means = nullptr;
};

// Generated for every schema enum: how many values it has and their names, in order.
template <typename E>
struct EnumInfo;

} // namespace haptics
