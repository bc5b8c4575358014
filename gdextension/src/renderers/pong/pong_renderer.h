#pragma once

// Haptic Battle Pong as the servo runs it (render mode PONG): the ball, the paddles and the
// effects (pong_sim.h) stepped every tick, so the ball-paddle contact closes at the
// servo rate, as in the paper and in CHAI3D's dynamic examples (the physics steps inside the
// haptic loop, the game only draws snapshots).
//
// Each tick: pick_up() takes the latest PongInput (seqlock) and every queued PongCommand
// (SPSC) off PongChannels, whatever the render mode, so a serve sent before the switch to
// PONG is not lost; render() steps the simulation with the device's state and returns the
// device player's hand force in device space, N, as its three force components (PongForce):
//   contact   the paddle's contact law (-n_s k_p delta, or c beyond d)
//   spin      the spinning ball's drag on the paddle (k_hr w x (a - p))
//   effects   the effects (recoil, hit, slow, heavy, remote)
// A HUD reads them there (get_forces()), or, with the world-space ball and paddles, from
// PongState (get_pong_state()["hand_force"]: the same three and the total). The continuous
// force is not low-pass filtered: it is position feedback (the
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

#include "core/render/renderer.h"
#include "core/render/renderer_info.h"
#include "core/render/settings_inbox.h"
#include "renderers/pong/pong_channels.h"
#include "renderers/pong/pong_port.h"
#include "renderers/pong/pong_sim.h"

#include <cstddef>
#include <cstdint>
#include <span>

namespace haptics {

// Its force components, in their order in ForceComponents::parts (PongForce), and its
// telemetry flags (TELEMETRY_FLAG_PONG_MODE, TELEMETRY_FLAG_PADDLE_CONTACT): pong.schema.toml.
static_assert(TELEMETRY_FLAG_PONG_MODE >= (1u << FIRST_RENDERER_FLAG_BIT));

class PongRenderer final : public Renderer {
public:
	using Config = PongConfig;
	using Channels = PongChannels;
	using Port = PongPort;
	static const RendererInfo &info();
	// What the field table's per-field ranges cannot say (validate_pong_config).
	static Status validate(const PongConfig &p_config);

	explicit PongRenderer(PongChannels &r_channels);

	void pick_up_settings(double p_dt_s, bool p_restart) override;
	void begin_session(double p_dt_s) override;
	void reset() override;
	void pick_up() override;
	bool heard_from_game() const override { return heard_from_game_; }
	bool planar() const override { return false; }
	void render(const RenderInput &p_input, RenderResult &r_result) override;
	void publish(const ForceComponents &p_forces, bool p_active) override;

	const PongSim &sim() const { return sim_; }

private:
	PongChannels &channels_;
	SettingsInbox<PongConfig> inbox_;
	PongConfig config_;
	PongSim sim_;
	uint64_t input_version_ = 0; // Of channels_.input, last taken; 0: take the latest.
	bool heard_from_game_ = false; // This tick took a PongInput the game sent.
	bool picked_up_ = false; // This tick took input or commands.
	uint64_t event_drops_ = 0; // Events the full queue refused this session.
};

} // namespace haptics
