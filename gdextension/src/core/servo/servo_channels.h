#pragma once

// Everything the game thread and the servo share, whatever renders; every member is
// lock-free and allocation-free after construction. Each renderer has channels of its own
// besides (RendererChannels).

#include "core/base/seqlock.h"
#include "core/base/spsc_queue.h"
#include "core/render/frame.h"
#include "core/servo/servo_config.h"
#include "core/servo/servo_output.h"
#include "core/servo/servo_stats.h"
#include "core/servo/telemetry.h"

#include "core/servo/servo.gen.h"

#include <atomic>
#include <cstddef>
#include <cstdint>

namespace haptics {

inline constexpr size_t IMPACT_QUEUE_CAPACITY = 64;
// TELEMETRY_QUEUE_CAPACITY: servo.schema.toml.

struct ServoChannels {
	Seqlock<GameFrame> frame; // Game -> servo, written by submit_frame only.
	// Game -> servo. Also the renderers' settings' generation: the game stores it after
	// storing any renderer's settings (RendererChannels), so the servo looks at theirs only
	// when this changed.
	Seqlock<ServoConfig> config;
	SpscQueue<ImpactEvent, IMPACT_QUEUE_CAPACITY> impacts; // Game -> servo.
	Seqlock<ServoOutput> output; // Servo -> game.
	SpscQueue<TelemetrySample, TELEMETRY_QUEUE_CAPACITY> telemetry; // Servo -> game.
	ServoStatsRecorder stats; // Servo -> game.
	std::atomic<uint64_t> queue_drops{ 0 }; // Impacts refused by a full queue (game side).
};

} // namespace haptics
