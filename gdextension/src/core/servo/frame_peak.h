#pragma once

// The largest force the device was given over the game's last frame or two, for a game that
// reads the forces once a frame: an impact lasts a few milliseconds, a frame 17, so a read of
// one tick's force caught a 2.14 N landing at 0.44 N. The windows follow the game's frames
// (a frame or another sign of it, Renderer::heard_from_game), and last at most MAX_WINDOW_S
// when none comes. Real-time safe: no allocation, no locks.

#include "core/base/vec3.h"

namespace haptics {

class FramePeak {
public:
	static constexpr double MAX_WINDOW_S = 0.1;

	void reset() { *this = FramePeak{}; }

	// The game was heard from: a new window begins.
	void next_window() {
		previous_ = latest_;
		latest_ = Vec3{};
		window_s_ = 0.0;
	}

	// One tick of p_dt_s wrote p_total.
	void add(const Vec3 &p_total, double p_dt_s) {
		if (window_s_ >= MAX_WINDOW_S) {
			next_window();
		}
		window_s_ += p_dt_s;
		if (is_finite(p_total) && length_squared(p_total) > length_squared(latest_)) {
			latest_ = p_total;
		}
	}

	// The largest total of this window and the one before (its vector at that tick).
	Vec3 peak() const { return length_squared(previous_) >= length_squared(latest_) ? previous_ : latest_; }

private:
	Vec3 latest_;
	Vec3 previous_;
	double window_s_ = 0.0;
};

} // namespace haptics
