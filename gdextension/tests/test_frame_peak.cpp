#include "core/servo/frame_peak.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

using namespace haptics;

namespace {

constexpr double TICK_S = 0.001;

// A landing's transient on the hand: 2.14 N along +y ringing down over 12 ms.
Vec3 landing(int p_tick_since) {
	if (p_tick_since < 0 || p_tick_since >= 12) {
		return Vec3{};
	}
	return Vec3{ 0.0, 2.14 * std::exp(-p_tick_since / 3.0) * std::cos(p_tick_since * 0.9), 0.0 };
}

} // namespace

TEST_CASE("frame peak: read once a frame, no peak of the 1 kHz force is missed") {
	// Frames every 17 ticks (a 60 Hz game); a landing starting at every offset into a frame,
	// read once at the end of each frame (after the tick that brings the next frame too).
	for (int start = 40; start < 40 + 17; ++start) {
		CAPTURE(start);
		FramePeak peak;
		double true_peak = 0.0;
		double read_peak = 0.0;
		double tick_read_peak = 0.0;
		for (int tick = 0; tick < 200; ++tick) {
			if (tick % 17 == 0) {
				peak.next_window();
			}
			const Vec3 total = landing(tick - start);
			peak.add(total, TICK_S);
			true_peak = std::max(true_peak, length(total));
			if (tick % 17 == 16) {
				read_peak = std::max(read_peak, length(peak.peak()));
				tick_read_peak = std::max(tick_read_peak, length(total));
			}
		}
		CHECK(read_peak == doctest::Approx(true_peak).epsilon(0.05));
		CHECK(true_peak == doctest::Approx(2.14));
		// What one tick's force read once a frame shows: mostly far less.
		CHECK(tick_read_peak <= true_peak);
	}
}

TEST_CASE("frame peak: a game that stops sending forgets an old peak within 0.2 s") {
	FramePeak peak;
	peak.add(Vec3{ 3.0, 0.0, 0.0 }, TICK_S);
	for (int tick = 0; tick < 150; ++tick) {
		peak.add(Vec3{ 0.1, 0.0, 0.0 }, TICK_S);
	}
	CHECK(length(peak.peak()) == doctest::Approx(3.0)); // Within two windows: still there.
	for (int tick = 0; tick < 60; ++tick) {
		peak.add(Vec3{ 0.1, 0.0, 0.0 }, TICK_S);
	}
	CHECK(length(peak.peak()) == doctest::Approx(0.1));
	// Non-finite totals never become the peak.
	peak.add(Vec3{ NAN, 0.0, 0.0 }, TICK_S);
	CHECK(is_finite(peak.peak()));
}
