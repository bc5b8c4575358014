#pragma once

// The whole configuration table: the servo's rows (core/servo/servo_config_fields.h), then
// each renderer's in the renderer table's order, each row reaching its owner's part of a
// RenderConfig. Validation, set_config, get_config and get_config_fields() for GDScript all
// walk it; a renamed key keeps its old name in its row and is accepted, with a deprecation
// warning, for one release.

#include "core/base/status.h"
#include "core/config/config_field.h"
#include "system/render_config.h"

#include <span>
#include <string_view>

namespace haptics {

std::span<const ConfigField> config_fields();
// The sections in table order, each once.
std::span<const char *const> config_sections();
// By key, or by old key; null when the section has no such field.
const ConfigField *find_config_field(std::string_view p_section, std::string_view p_key);

// A row of config_fields() on p_config (its owner's part of it).
double config_value(const RenderConfig &p_config, const ConfigField &p_field);
// Only with a value check_config_value accepted.
void set_config_value(RenderConfig &r_config, const ConfigField &p_field, double p_value);

// Every field against its row, the limits that join a renderer's fields (its validate()),
// and the render mode.
Status validate_render_config(const RenderConfig &p_config);

} // namespace haptics
