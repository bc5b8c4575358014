#pragma once

// Everything the game thread and the constraint renderer share, each channel with one
// writer, all lock-free (ConstraintPort is the game's end):
//   settings  game -> servo  seqlock             ConstraintConfig
//   geometry  game <-> servo two mailboxes        the maze's walls; the ones to free back
//   state     servo -> game  seqlock             ProxyState, when it changes

#include "core/base/seqlock.h"
#include "core/base/vec2.h"
#include "core/render/renderer_channels.h"
#include "renderers/constraint/constraint_config.h"
#include "renderers/constraint/geometry_exchange.h"

#include <cstdint>

namespace haptics {

struct ProxyState {
	// Maze units; filled while the constraint renderer is the active one. Until the proxy is
	// placed `proxy` is the goal, i.e. the device mapped into the maze.
	Vec2 proxy;
	Vec2 goal;
	uint32_t constraints = 0; // Walls holding the proxy: 0 free, 1 sliding, 2+ stopped.
	bool placed = false;
	uint64_t updates = 0; // Proxy updates this session (1 per tick, or 1 per frame).
	// The walls the servo holds, whatever the render mode: how many geometries it has picked
	// up since the engine was made (a new geometry has taken effect once this moves), and
	// their count.
	uint64_t geometry_generation = 0;
	uint32_t geometry_segments = 0;
};

struct ConstraintChannels : RendererChannels {
	Seqlock<ConstraintConfig> settings;
	GeometryExchange geometry;
	Seqlock<ProxyState> state;

	void collect() override { geometry.collect(); }
};

} // namespace haptics
