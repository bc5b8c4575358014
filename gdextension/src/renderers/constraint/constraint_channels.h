#pragma once

// Everything the game thread and the constraint renderer share, each channel with one
// writer, all lock-free (ConstraintPort is the game's end):
//   settings  game -> servo  seqlock             ConstraintConfig
//   geometry  game <-> servo two mailboxes        the maze's walls; the ones to free back
//   state     servo -> game  seqlock             ProxyState, when it changes

#include "core/base/seqlock.h"
#include "core/base/vec2.h"
#include "core/render/renderer_channels.h"
#include "renderers/constraint/constraint.gen.h"
#include "renderers/constraint/constraint_config.h"
#include "renderers/constraint/geometry_exchange.h"

#include <cstdint>

namespace haptics {

// ProxyState: constraint.schema.toml.

struct ConstraintChannels : RendererChannels {
	Seqlock<ConstraintConfig> settings;
	GeometryExchange geometry;
	Seqlock<ProxyState> state;

	void collect() override { geometry.collect(); }
};

} // namespace haptics
