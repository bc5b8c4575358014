#pragma once

// Everything the game thread and the vehicle renderer share, each channel with one writer,
// all lock-free (VehiclePort is the game's end):
//   settings  game -> servo  seqlock   VehicleConfig
//   frame     game -> servo  seqlock   the latest VehicleFrame, picked up every tick
//   state     servo -> game  seqlock   VehicleState, every tick while the renderer is active

#include "core/base/seqlock.h"
#include "core/render/renderer_channels.h"
#include "renderers/vehicle/vehicle.gen.h"

namespace haptics {

struct VehicleChannels : RendererChannels {
	Seqlock<VehicleConfig> settings;
	Seqlock<VehicleFrame> frame;
	Seqlock<VehicleState> state;
};

} // namespace haptics
