#pragma once

// The renderer table (renderer_table.h) as data, for what walks it at run time: the binding
// (RENDER_MODE_* and TELEMETRY_FLAG_* constants, the names of get_forces()) and the
// configuration table (config_table.h).

#include "core/render/renderer_info.h"

#include <span>

namespace haptics {

struct RegisteredRenderer {
	const char *name; // "movement"
	const char *mode_constant; // "RENDER_MODE_MOVEMENT"
	const RendererInfo *info;
};

// In render-mode order: a row's index is its mode's value.
std::span<const RegisteredRenderer> registered_renderers();

} // namespace haptics
