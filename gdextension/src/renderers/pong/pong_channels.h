#pragma once

// Everything the game thread and the Pong renderer share, each channel with one writer, all
// lock-free and allocation-free after construction (PongPort is the game's end):
//   settings  game -> servo  seqlock      PongConfig
//   input     game -> servo  seqlock      the latest PongInput, picked up every tick
//   commands  game -> servo  SPSC ring    a full ring refuses the command (an error to the game)
//   state     servo -> game  seqlock      PongState after every tick
//   events    servo -> game  SPSC ring    a full ring drops the event (PongState::events_dropped)

#include "core/base/seqlock.h"
#include "core/base/spsc_queue.h"
#include "core/render/renderer_channels.h"
#include "renderers/pong/pong_config.h"
#include "renderers/pong/pong_input.h"
#include "renderers/pong/pong_output.h"

#include <cstddef>

namespace haptics {

// A frame sends a few commands at most; 64 is a second of them with the servo stopped.
inline constexpr size_t PONG_COMMAND_QUEUE_CAPACITY = 64;
// PONG_EVENT_QUEUE_CAPACITY (pong.schema.toml): a rally raises a few events a second; 256
// outlasts seconds of a game that does not drain.

struct PongChannels : RendererChannels {
	Seqlock<PongConfig> settings;
	Seqlock<PongInput> input;
	SpscQueue<PongCommand, PONG_COMMAND_QUEUE_CAPACITY> commands;
	Seqlock<PongState> state;
	SpscQueue<PongEvent, PONG_EVENT_QUEUE_CAPACITY> events;
};

} // namespace haptics
