#pragma once

// Haptic Battle Pong as the servo runs it (RenderMode::PONG): the ball, the paddles and the
// effects (pong/pong_sim.h) stepped every tick, so the ball-paddle contact closes at the
// servo rate, as in the paper and in CHAI3D's dynamic examples (the physics steps inside the
// haptic loop, the game only draws snapshots).
//
// Each tick: pick_up() takes the latest PongInput (seqlock) and every queued PongCommand
// (SPSC) off PongChannels, whatever the render mode, so a serve sent before the switch to
// PONG is not lost; render() steps the simulation with the device's state and returns the
// device player's hand force in device space, N, as force components:
//   normal    the paddle's contact law (-n_s k_p delta, or c beyond d)
//   friction  the spinning ball's drag on the paddle (k_hr w x (a - p))
//   weight    the effects (recoil, hit, slow, heavy, remote)
// drag and inertia are zero. A HUD reads them there (get_forces()), or, with the world-space
// ball and paddles, from PongState (get_pong_state()["hand_force"]: contact, spin, effects,
// total). The continuous force is not low-pass filtered: it is position feedback (the
// paddle's penetration follows the stylus), and a filter in that loop adds lag that makes
// the ball feel spongy and can destabilise it. The force scale, transients and the safety
// stage apply after it, as for every renderer.
//
// The game's PongInput is this renderer's heartbeat (heard_from_game): a game in PONG mode
// sends it every frame instead of frames. publish() stores the PongState every tick while
// active (and on a tick that picked up input or commands while not), and render() moves the
// step's events onto the events queue, counting those a full queue drops.
//
// 3D: planar() is false, so no plane hold pulls the stylus's depth axis. No allocation.

#include "core/renderer.h"
#include "pong/pong_channels.h"
#include "pong/pong_sim.h"

#include <cstdint>

namespace haptics {

class PongRenderer final : public Renderer {
public:
	explicit PongRenderer(PongChannels &r_channels);

	void begin_session(double p_dt_s) override;
	void configure(const RenderConfig &p_config, double p_dt_s) override;
	void reset() override;
	void pick_up() override;
	bool heard_from_game() const override { return heard_from_game_; }
	bool planar() const override { return false; }
	void render(const RenderInput &p_input, RenderResult &r_result) override;
	void publish(ServoOutput &r_output, bool p_active) const override;

	const PongSim &sim() const { return sim_; }

private:
	PongChannels &channels_;
	PongSim sim_;
	uint64_t input_version_ = 0; // Of channels_.input, last taken; 0: take the latest.
	bool heard_from_game_ = false; // This tick took a PongInput the game sent.
	bool picked_up_ = false; // This tick took input or commands.
	uint64_t event_drops_ = 0; // Events the full queue refused this session.
};

} // namespace haptics
