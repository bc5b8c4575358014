#pragma once

// The game's end of the Pong renderer: the ball and paddles live in the servo (pong_sim.h);
// world space is Godot's 3D world, the hand forces are the device player's device space.
// Game thread only:
//   each frame:   port.set_input(input)    (also the watchdog's heartbeat in PONG mode)
//   on events:    port.push_command(...)   (serve, effects)
//   each frame:   port.state(), port.drain_events(...)
// The same through RendererPort, as the game sends them (pong.schema.toml): it takes
// PongInput and PongCommand, and gives PongState and PongEventBatch (the drained events).
// A networked match's server also checks its master's ball here (ball_witness.h): it sends a
// PongWitnessCheck per state and reads the PongWitnessVerdict, and sends the master's own
// poses as PongWitnessPose; set_input feeds the check the servo's paddles every frame.

#include "core/base/status.h"
#include "core/render/renderer_port.h"
#include "renderers/pong/ball_witness.h"
#include "renderers/pong/pong_channels.h"

#include <cstddef>

namespace haptics {

class PongPort final : public RendererPort {
public:
	explicit PongPort(PongChannels &r_channels);

	Status receive(std::span<const uint8_t> p_message) override;
	Status give(uint32_t p_value_id, std::vector<uint8_t> &r_bytes) override;

	// The latest paddles and modes; validated (pong_validation.h), then published lock-free.
	// On error the previous input stays in force.
	Status set_input(const PongInput &p_input);
	// Queues a command for the servo's next tick (also while another renderer runs, so a
	// serve may precede the switch to PONG). Validated against the current settings; a full
	// queue (the servo not ticking) is an error and the command is not queued.
	Status push_command(const PongCommand &p_command);
	// After the latest tick in PONG mode.
	PongState state() const;
	// Pops up to p_max events, oldest first, into r_out; returns how many.
	size_t drain_events(PongEvent *r_out, size_t p_max);
	// Checks a state of the master's ball (ball_witness.h) at the servo's latest time.
	const PongWitnessVerdict &check_ball(const PongWitnessCheck &p_check);

private:
	PongChannels &channels_;
	BallWitness witness_;
	PongWitnessVerdict verdict_;
};

} // namespace haptics
