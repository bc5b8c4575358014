#pragma once

// One setting the game can change, described once: the section and key the game spells it
// with (HapticsServer.set_config / get_config), its kind, range and unit, and how to reach it
// in the settings struct of its owner (the servo's ServoConfig, or one renderer's Config).
// Each owner lists its rows next to its struct (core/servo/servo_config_fields.cpp,
// renderers/<name>/<name>_config_fields.cpp); the engine joins them into the one table
// (system/config_table.h) that validation, the binding's dictionary reader and writer, and
// get_config_fields() for GDScript walk, so a field is named and bounded in one place.
//
// Keys end in their unit (_s, _hz, _m, _n, _n_per_s, _n_per_m, _n_per_kg, _n_s_per_m) unless
// the value is dimensionless or in maze units. Values travel as doubles: a COUNT is a whole
// number, a FLAG 0 or 1, a CHOICE the enum's value.

#include "core/base/status.h"

#include <cstdint>
#include <span>

namespace haptics {

enum class FieldKind : int32_t {
	NUMBER = 0,
	COUNT = 1,
	FLAG = 2,
	CHOICE = 3,
};

struct ConfigField {
	const char *section;
	const char *key;
	FieldKind kind;
	double min;
	double max;
	const char *unit; // For people ("N/s"); "" when dimensionless.
	// NUMBER: when set, 0 is allowed besides [min, max] and means this ("the device's limit").
	const char *zero_means;
	// CHOICE: the values' names in enum order (the binding also accepts these strings).
	std::span<const char *const> choices;
	// The key before the unit suffixes were made consistent: the binding still accepts it,
	// with a deprecation warning, for one release. Null when the key never changed.
	const char *old_key;
	// On the owner's settings struct, the type the row's HAPTICS_CONFIG_FIELD names
	// (config_field_access.h); the engine hands each row its owner's.
	double (*get)(const void *p_settings);
	void (*set)(void *p_settings, double p_value); // Only with a value check_config_value accepted.
};

// OK when p_value is acceptable for the field; the message names "section.key".
Status check_config_value(const ConfigField &p_field, double p_value);

} // namespace haptics
