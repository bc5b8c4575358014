#pragma once

// Changes part of an engine's configuration the way a game does: read it, modify a copy,
// hand the whole of it back (HapticsEngine::configure validates it as one).

#include "engine/haptics_engine.h"

#include <utility>

namespace haptics {

template <typename F>
Status reconfigure(HapticsEngine &r_engine, F &&p_change) {
	RenderConfig config = r_engine.config();
	std::forward<F>(p_change)(config);
	return r_engine.configure(config);
}

} // namespace haptics
