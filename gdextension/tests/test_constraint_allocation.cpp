// "No allocation in the tick" for the constraint renderer, checked: malloc itself is
// interposed (glibc supports replacing it; this one forwards to __libc_malloc, so free,
// calloc and realloc stay consistent) and counts calls made while a manual step runs. That
// catches operator new too, without touching the operator new test_tick_allocation.cpp
// replaces. It covers the ticks that pick up new walls from the exchange. Skipped under the
// sanitizers, which bring their own allocator.

#include "renderers/constraint/constraint_port.h"
#include "system/haptics_system.h"
#include "system_config.h"
#include "test_proxy_geometry.h"

#include <doctest/doctest.h>

#include <atomic>
#include <cstddef>
#include <cstdlib>

#if !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__) && defined(__GLIBC__)
#define HAPTICS_COUNT_MALLOC 1

extern "C" void *__libc_malloc(size_t p_size);

namespace {
std::atomic<bool> g_watching{ false };
std::atomic<unsigned long> g_mallocs{ 0 };
} // namespace

extern "C" void *malloc(size_t p_size) noexcept {
	if (g_watching.load(std::memory_order_relaxed)) {
		g_mallocs.fetch_add(1, std::memory_order_relaxed);
	}
	return __libc_malloc(p_size);
}
#endif

using namespace haptics;

TEST_CASE("constraint tick allocates nothing: 1 kHz and 50 Hz proxy, walls swapped in") {
#ifdef HAPTICS_COUNT_MALLOC
	const std::vector<Segment2> walls = test::perfect_maze(30, 10.0, 8);
	MazeMapping mapping;
	mapping.maze_min = { 0.0, 0.0 };
	mapping.maze_max = { 300.0, 300.0 };
	mapping.workspace_half_extent_m = 0.09;
	HapticsSystem system;
	SimulatedDeviceConfig device;
	device.rigid_hand = true;
	REQUIRE(system.open_simulated_device(device));
	ConstraintPort maze(system.renderers().constraint.channels);
	REQUIRE(maze.set_geometry(walls.data(), walls.size(), mapping));
	REQUIRE(reconfigure(system, [](RenderConfig &c) { c.servo.render_mode = RenderMode::CONSTRAINT; }));
	ConstraintConfig config;
	config.proxy_radius = 3.0;
	unsigned long allocations = 0;
	for (int k = 0; k < 4000; ++k) {
		if (k == 2000) {
			config.update = ProxyUpdate::FRAME;
			REQUIRE(reconfigure(system, [&](RenderConfig &c) { c.constraint = config; }));
		}
		if (k % 500 == 250) { // New walls (built here, outside the watched step).
			REQUIRE(maze.set_geometry(walls.data(), walls.size() - static_cast<size_t>(k / 500), mapping));
		}
		const double t = k * 0.001;
		REQUIRE(system.set_hand_target({ 0.06 * std::sin(4.0 * t), 0.06 * std::sin(5.3 * t), 0.0 }));
		if (k % 20 == 0) {
			REQUIRE(system.submit_frame(Frame{}));
		}
		g_mallocs.store(0);
		g_watching.store(true);
		const Status status = system.step(0.001);
		g_watching.store(false);
		allocations += g_mallocs.load();
		REQUIRE(status);
	}
	CHECK(maze.state().placed);
	CHECK(maze.state().updates > 2000);
	CHECK(allocations == 0);
	// The counter works.
	g_mallocs.store(0);
	g_watching.store(true);
	void *volatile probe = std::malloc(24);
	g_watching.store(false);
	std::free(probe);
	CHECK(g_mallocs.load() == 1);
#else
	MESSAGE("malloc counting is off under sanitizers");
#endif
}
