// RenderConfig <-> GDScript dictionaries, driven by the engine's field table
// (system/config_table.h): a section is a Dictionary of key -> value, a NUMBER a float, a
// COUNT an int, a FLAG a bool, a CHOICE an int (the enum's value, e.g.
// HapticsServer.PROXY_UPDATE_FRAME_RATE) or its name ("frame").
#pragma once

#include <string>

#include "binding/containers.h"
#include "system/render_config.h"

namespace haptics::binding {

// Applies the keys present in p_values to r_config's section p_section; each value is
// checked against its field's range before it is stored. r_config is only meaningful when
// true is returned. Old key names are accepted with a deprecation warning.
bool apply_config_section(const std::string &p_section, const gd::Dictionary &p_values, RenderConfig &r_config,
		std::string &r_error);
// Every section with every key.
gd::Dictionary config_to_dictionary(const RenderConfig &p_config);
// The field table for scripts and tools: one Dictionary per field with section, key, kind
// ("number", "count", "flag", "choice"), min, max, unit, default, zero_means, choices,
// old_key.
gd::Array config_fields_to_array();

} // namespace haptics::binding
