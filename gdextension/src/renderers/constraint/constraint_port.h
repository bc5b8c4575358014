#pragma once

// The game's end of the constraint renderer (position control against a maze's walls): the
// walls in, the proxy out. Game thread only; any time, also while rendering.
//   at level load:   port.set_geometry(walls, count, mapping), then the engine's
//                    configuration with render_mode = the constraint renderer's;
//   each physics tick: the engine's submit_frame (empty contacts are fine: the heartbeat);
//   each frame:      draw the avatar at port.state().proxy.

#include "core/base/status.h"
#include "core/render/renderer_port.h"
#include "renderers/constraint/constraint_channels.h"
#include "renderers/constraint/maze_mapping.h"
#include "renderers/constraint/swept_disc.h"

#include <cstddef>

namespace haptics {

class ConstraintPort final : public RendererPort {
public:
	explicit ConstraintPort(ConstraintChannels &r_channels);

	// As the game sends them (constraint.schema.toml): it takes MazeWalls (set_geometry) and
	// gives ProxyState (state()).
	Status receive(std::span<const uint8_t> p_message) override;
	Status give(uint32_t p_value_id, std::vector<uint8_t> &r_bytes) override;

	// The maze's static walls (maze units; polygons as closed chains, see
	// append_closed_chain) and how the device's workspace maps onto the maze. Validated
	// (finite, non-degenerate, count <= MAX_CONSTRAINT_SEGMENTS: the message names the
	// index), copied and indexed here, on this thread; then handed to the servo lock-free,
	// which switches to it at its next tick. On error the previous geometry stays in force.
	// p_count == 0 is a maze without walls.
	Status set_geometry(const Segment2 *p_segments, size_t p_count, const MazeMapping &p_mapping);
	// After the latest tick. While the proxy is not placed (no geometry yet, or the device
	// maps into a wall) `proxy` is the goal, the device mapped into the maze.
	ProxyState state() const;

private:
	ConstraintChannels &channels_;
};

} // namespace haptics
