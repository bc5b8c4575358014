#pragma once

// Hands wall geometry from the game thread to the servo thread while the servo runs, without
// a lock and without the servo ever allocating or freeing.
//
// Two single-slot mailboxes of owning pointers:
//   pending  game -> servo: the newest geometry not yet picked up;
//   retired  servo -> game: the geometry the servo stopped using, for the game to free.
// The game publishes by exchanging `pending` (a geometry the servo never picked up comes
// back to it and is freed there: nobody else ever saw it). At the start of a tick the servo
// takes `pending` only when `retired` is empty, so it always has somewhere to put the one it
// replaces; otherwise it keeps rendering the current one and tries again next tick. The game
// empties `retired` whenever it publishes and whenever it calls collect() (the engine does so
// on every submit_frame, i.e. at 50 Hz), so a swap completes within a frame.
//
// Each pointer is owned by exactly one side at any moment; the atomic exchanges are the
// hand-overs (acquire/release, so the geometry's contents are visible before its pointer).
// A generation counter tells the servo's renderer that the geometry changed even if a new
// one happens to be allocated at the address of a freed old one.
//
// Threading: publish() and collect() from the game thread only; acquire() from the thread
// that ticks the servo (the servo thread, or the game thread in manual step mode). The
// destructor frees everything: the servo must be stopped by then.

#include "renderers/constraint/constraint_geometry.h"

#include <atomic>
#include <cstdint>
#include <memory>

namespace haptics {

class GeometryExchange {
public:
	struct Current {
		const ConstraintGeometry *geometry = nullptr; // Null until the first pick-up.
		uint64_t generation = 0; // Increments at every pick-up.
	};

	GeometryExchange() = default;
	~GeometryExchange();
	GeometryExchange(const GeometryExchange &) = delete;
	GeometryExchange &operator=(const GeometryExchange &) = delete;

	// Game thread.
	void publish(std::unique_ptr<ConstraintGeometry> p_geometry);
	void collect(); // Frees what the servo retired, if anything.

	// Servo side, once per tick: switches to a pending geometry when it can. Never blocks,
	// allocates or frees.
	Current acquire();
	Current current() const { return { current_, generation_ }; } // Servo side.

private:
	std::atomic<ConstraintGeometry *> pending_{ nullptr };
	std::atomic<ConstraintGeometry *> retired_{ nullptr };
	ConstraintGeometry *current_ = nullptr; // Servo side; owned here.
	uint64_t generation_ = 0;
};

} // namespace haptics
