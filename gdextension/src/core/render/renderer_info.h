#pragma once

// What the system and the game know of a renderer without running it. Each renderer
// describes itself once (its static info()); the renderer table (system/renderer_table.h)
// names it and gives its render mode.

#include "core/render/force_components.h"

#include <cstdint>
#include <span>

namespace haptics {

// Telemetry flag bits below this one are the servo's own (core/servo/telemetry.h); a
// renderer raises bits from here up, each renderer its own (a doctest checks they differ).
inline constexpr uint32_t FIRST_RENDERER_FLAG_BIT = 7;

struct RendererInfo {
	// What get_forces() calls ForceComponents::parts while this renderer is active, in order;
	// at most MAX_FORCE_PARTS.
	std::span<const char *const> force_names;
	// The telemetry flag bits it raises (its schema's TELEMETRY_FLAG_* constants name them).
	std::span<const uint32_t> telemetry_flags;
};

} // namespace haptics
