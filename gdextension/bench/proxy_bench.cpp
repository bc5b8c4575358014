// The finite proxy's update cost as the walls grow: uniform grid against brute force, same
// run, same mazes, same device paths, so the ratio is the broad phase's and nothing else's.
//
// Mazes: random perfect mazes of 9, 31 and 99 cells a side (100, 1 024 and 10 000 walls),
// cells of 10 units, proxy radius 3, the workspace (0.1 m disc) mapped onto the whole maze.
// Two device paths per maze, 5 000 updates each (5 s at 1 kHz):
//   sweep  a Lissajous across the whole workspace at up to ~0.2 m/s: the hand mostly far
//          from a proxy held behind walls, i.e. long casts (position control in a maze);
//   local  the hand pushing around the proxy within ~2 corridor widths: sliding along
//          walls and into corners, the common case while playing.
// Each update is timed on its own (steady_clock, ~20-30 ns of overhead included in both
// columns); p50 and p99 over the 5 000.

#include "bench_report.h"

#include "renderers/constraint/constraint_geometry.h"
#include "renderers/constraint/finite_proxy.h"
#include "renderers/constraint/maze_mapping.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <numbers>
#include <random>
#include <utility>
#include <vector>

// The same random perfect mazes the proxy tests use.
#include "../tests/test_proxy_geometry.h"

namespace haptics::bench {

namespace {

constexpr double CELL = 10.0;
constexpr double RADIUS = 3.0;
constexpr int UPDATES = 5000;
constexpr int WARM_UP = 200;

struct PathRun {
	double p50_ns = 0.0;
	double p99_ns = 0.0;
	double max_ns = 0.0;
	double mean_sweeps = 0.0;
	double contact_fraction = 0.0;
	std::vector<Vec2> trace; // Proxy positions, to check the two broad phases agree.
};

PathRun run_path(const ConstraintGeometry &p_geometry, const MazeTransform &p_transform, bool p_local) {
	FiniteProxy proxy;
	const Vec2 start = p_transform.to_maze({ 0.0, 0.0 });
	proxy.try_place(p_geometry, start, RADIUS);
	std::mt19937 random(17);
	std::uniform_real_distribution<double> unit(-1.0, 1.0);
	std::vector<double> times;
	times.reserve(UPDATES);
	PathRun run;
	run.trace.reserve(UPDATES);
	double sweeps = 0.0;
	int contacts = 0;
	for (int k = -WARM_UP; k < UPDATES; ++k) {
		Vec2 goal;
		if (p_local) {
			goal = proxy.position() + Vec2{ unit(random), unit(random) } * (2.0 * CELL);
		} else {
			const double t = (k + WARM_UP) * 0.001;
			goal = p_transform.to_maze({ 0.065 * std::sin(2.0 * std::numbers::pi * 0.37 * t),
					0.065 * std::sin(2.0 * std::numbers::pi * 0.53 * t + 0.4) });
		}
		const auto begin = std::chrono::steady_clock::now();
		proxy.update(p_geometry, goal, RADIUS, 6);
		const auto end = std::chrono::steady_clock::now();
		if (k >= 0) {
			times.push_back(std::chrono::duration<double, std::nano>(end - begin).count());
			sweeps += proxy.last_sweeps();
			contacts += proxy.active_constraints() > 0 ? 1 : 0;
			run.trace.push_back(proxy.position());
		}
	}
	std::sort(times.begin(), times.end());
	run.p50_ns = times[times.size() / 2];
	run.p99_ns = times[times.size() * 99 / 100];
	run.max_ns = times.back();
	run.mean_sweeps = sweeps / UPDATES;
	run.contact_fraction = static_cast<double>(contacts) / UPDATES;
	return run;
}

} // namespace

std::vector<ProxyBenchResult> run_proxy_benchmarks() {
	std::vector<ProxyBenchResult> results;
	for (const int cells : { 9, 31, 99 }) {
		const std::vector<Segment2> walls = haptics::test::perfect_maze(cells, CELL, 2024);
		MazeMapping mapping;
		mapping.maze_max = { cells * CELL, cells * CELL };
		mapping.workspace_half_extent_m = 0.1;
		std::unique_ptr<ConstraintGeometry> grid;
		std::unique_ptr<ConstraintGeometry> brute;
		ConstraintGeometry::build(walls.data(), walls.size(), mapping, BroadPhase::UNIFORM_GRID, grid);
		ConstraintGeometry::build(walls.data(), walls.size(), mapping, BroadPhase::BRUTE_FORCE, brute);
		const MazeTransform transform = resolve_maze_mapping(mapping, 0.1);
		for (const bool local : { false, true }) {
			const PathRun fast = run_path(*grid, transform, local);
			const PathRun slow = run_path(*brute, transform, local);
			ProxyBenchResult result;
			result.segments = walls.size();
			result.path = local ? "local" : "sweep";
			result.grid_columns = grid->grid_columns();
			result.grid_rows = grid->grid_rows();
			result.grid_p50_ns = fast.p50_ns;
			result.grid_p99_ns = fast.p99_ns;
			result.grid_max_ns = fast.max_ns;
			result.brute_p50_ns = slow.p50_ns;
			result.brute_p99_ns = slow.p99_ns;
			result.brute_max_ns = slow.max_ns;
			result.mean_sweeps = fast.mean_sweeps;
			result.contact_fraction = fast.contact_fraction;
			result.identical = fast.trace == slow.trace;
			results.push_back(result);
		}
	}
	return results;
}

} // namespace haptics::bench
