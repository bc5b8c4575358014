#pragma once

// Changes part of a HapticsSystem's configuration the way a game does: read it, modify a copy,
// hand the whole of it back (HapticsSystem::configure validates it as one).

#include "system/haptics_system.h"

#include <utility>

namespace haptics {

template <typename F>
Status reconfigure(HapticsSystem &r_system, F &&p_change) {
	RenderConfig config = r_system.config();
	std::forward<F>(p_change)(config);
	return r_system.configure(config);
}

} // namespace haptics
