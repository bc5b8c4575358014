#pragma once

// What the game thread and one renderer share (its settings, and inputs and outputs of its
// own such as the maze's walls or Pong's ball), all lock-free: each renderer's Channels
// derives from this, and the engine owns one per renderer next to the renderer.

namespace haptics {

struct RendererChannels {
	virtual ~RendererChannels() = default;

	// Game thread: frees what the servo has finished with (the constraint renderer's replaced
	// walls), so the next hand-over is never held up. Called after each manual step, each
	// submitted frame and when rendering stops.
	virtual void collect() {}
};

} // namespace haptics
