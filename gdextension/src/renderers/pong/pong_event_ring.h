#pragma once

// The events one PongSim step raised, in order, for whoever runs the sim to take away (the
// renderer moves them onto the servo -> game queue every tick; tests read them directly).
// Single-threaded, fixed capacity, no allocation: a full ring drops the newest and counts.

#include "renderers/pong/pong_output.h"

#include <cstddef>
#include <cstdint>

namespace haptics {

class PongEventRing {
public:
	// A tick raises a handful at most (a corner bounce, a paddle, a territory): this holds
	// several ticks' worth for a caller that drains less often.
	static constexpr size_t CAPACITY = 64;

	void push(const PongEvent &p_event) {
		if (count_ == CAPACITY) {
			++dropped_;
			return;
		}
		events_[(head_ + count_) % CAPACITY] = p_event;
		++count_;
	}
	bool pop(PongEvent &r_event) {
		if (count_ == 0) {
			return false;
		}
		r_event = events_[head_];
		head_ = (head_ + 1) % CAPACITY;
		--count_;
		return true;
	}
	void clear() {
		head_ = 0;
		count_ = 0;
	}
	size_t size() const { return count_; }
	uint64_t dropped() const { return dropped_; }
	void reset_dropped() { dropped_ = 0; }

private:
	PongEvent events_[CAPACITY];
	size_t head_ = 0;
	size_t count_ = 0;
	uint64_t dropped_ = 0;
};

} // namespace haptics
