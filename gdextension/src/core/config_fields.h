#pragma once

// Every RenderConfig field the game can set, described once: the section and key the game
// spells it with (HapticsServer.set_config / get_config), its kind, range and unit, and how to
// reach it in the struct. Validation (validate_render_config), the binding's dictionary
// reader and writer, and get_config_fields() for GDScript all walk this table, so a field is
// named and bounded in one place.
//
// Keys end in their unit (_s, _hz, _m, _n, _n_per_s, _n_per_m, _n_per_kg, _n_s_per_m) unless
// the value is dimensionless or in maze units. Values travel as doubles: a COUNT is a whole
// number, a FLAG 0 or 1, a CHOICE the enum's value.

#include "core/config.h"
#include "core/status.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

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
	double (*get)(const RenderConfig &);
	void (*set)(RenderConfig &, double); // Only with a value check_config_value accepted.
};

std::span<const ConfigField> config_fields();
// The sections in table order, each once.
std::span<const char *const> config_sections();
// By key, or by old key; null when the section has no such field.
const ConfigField *find_config_field(std::string_view p_section, std::string_view p_key);
// OK when p_value is acceptable for the field; the message names "section.key".
Status check_config_value(const ConfigField &p_field, double p_value);

} // namespace haptics
