#pragma once

// The constraint-based renderer as the servo runs it: device position -> goal in the maze ->
// finite proxy update -> F = k_c (proxy - device), in newtons, device space
// (constraint_solver.h).
//
//   goal  = to_maze(device.xy)
//   F.xy  = k_c (to_device(proxy) - device.xy),   F.z = 0
// Only the normal force, as in the study: the proxy is frictionless, so the force is always
// along the normals of the walls holding it; it is its one force component, `wall`
// (ConstraintForce). z is left free (the maze is planar). The
// force is not low-pass filtered: a filter inside a position-feedback loop adds phase lag,
// which makes a stiff wall spongy and can make it unstable, and the force is already
// continuous at the servo rate.
//
// The renderer follows the geometry the servo currently holds (GeometryExchange, picked up
// every tick whatever the render mode). When the geometry changes, the proxy keeps its place
// if the disc still fits there in the new walls (re-sending the same maze must not teleport
// the avatar through a wall), and is re-placed otherwise. It is re-placed too on reset() (a
// new session, a switch of render mode) and when the radius changes. Until it is placed the
// force is zero. Its state for the game (ProxyState) is stored every tick while active, and
// when the walls change while not.
//
// No allocation; state is the proxy, the resolved mapping and the last configuration.

#include "core/render/renderer.h"
#include "core/render/renderer_info.h"
#include "core/render/settings_inbox.h"
#include "renderers/constraint/constraint.gen.h"
#include "renderers/constraint/constraint_channels.h"
#include "renderers/constraint/constraint_port.h"
#include "renderers/constraint/constraint_solver.h"

#include <cstddef>
#include <cstdint>
#include <span>

namespace haptics {

// Its one force component, the walls' push: WALL_FORCE (ConstraintForce, constraint.schema.toml).

// Its telemetry flags (RendererInfo::telemetry_flags): TELEMETRY_FLAG_CONSTRAINT_MODE and
// TELEMETRY_FLAG_PROXY_CONTACT, constraint.schema.toml.
static_assert(TELEMETRY_FLAG_CONSTRAINT_MODE >= (1u << FIRST_RENDERER_FLAG_BIT));

class ConstraintRenderer final : public Renderer {
public:
	using Config = ConstraintConfig;
	using Channels = ConstraintChannels;
	using Port = ConstraintPort;
	static const RendererInfo &info();

	explicit ConstraintRenderer(ConstraintChannels &r_channels);

	void pick_up_settings(double p_dt_s, bool p_restart) override;
	void begin_session(double p_dt_s) override;
	void reset() override;
	void pick_up() override;
	void render(const RenderInput &p_input, RenderResult &r_result) override;
	void publish(const ForceComponents &p_forces, bool p_active) override;

private:
	ConstraintChannels &channels_;
	SettingsInbox<ConstraintConfig> inbox_;
	ConstraintConfig config_;
	ConstraintSolver solver_;
	ConstraintOutput last_;
	uint64_t updates_ = 0;
	// What publish() stored last, so an inactive renderer stores only what changed.
	ProxyState published_;
	bool published_active_ = false;
};

} // namespace haptics
