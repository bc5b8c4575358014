#pragma once

// The force of one servo tick, piece by piece, for the HUD and telemetry. The active renderer
// fills its own components (`parts`, which it names: RendererInfo::force_names, e.g. the
// movement renderer's normal, friction, weight, drag and inertia, Pong's contact, spin and
// effects) and their sum; the servo pipeline fills the rest.

#include "core/base/vec3.h"

#include <array>
#include <cstddef>

namespace haptics {

// The most components a renderer may name (and telemetry has columns for).
inline constexpr size_t MAX_FORCE_PARTS = 5;

struct ForceComponents {
	// In the order of the active renderer's force names; parts it does not name are zero.
	std::array<Vec3, MAX_FORCE_PARTS> parts{};
	Vec3 continuous; // The parts' sum, before smoothing.
	Vec3 smoothed; // continuous after the renderer's filtering, slew limit and watchdog fade
	Vec3 impact; // Sum of the impact transients, raw (not smoothed)
	Vec3 total; // What was written to the device: ramp and clamp applied
};

} // namespace haptics
