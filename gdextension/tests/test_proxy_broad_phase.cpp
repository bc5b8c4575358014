// The proxy's geometry: validation of the walls and the mapping (named index, clear
// message), the workspace mapping, polygon outlines, and the uniform grid broad phase
// (never misses a wall the brute force would test, reports each one once).

#include "renderers/constraint/constraint_geometry.h"
#include "renderers/constraint/maze_mapping.h"
#include "renderers/constraint/swept_disc.h"
#include "test_proxy_geometry.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <random>
#include <vector>

using namespace haptics;

namespace {

constexpr double NaN = std::numeric_limits<double>::quiet_NaN();

bool mentions(const Status &p_status, const char *p_text) {
	return std::strstr(p_status.message(), p_text) != nullptr;
}

// Distance between segments [p, q] and [a, b]: 0 when they cross, else the smallest
// endpoint-to-segment distance.
double segment_distance(const Vec2 &p_p, const Vec2 &p_q, const Segment2 &p_segment) {
	const Segment2 query{ p_p, p_q };
	const Vec2 d1 = p_q - p_p;
	const Vec2 d2 = p_segment.b - p_segment.a;
	const double denominator = cross(d1, d2);
	if (std::abs(denominator) > 1e-12) { // Crossing?
		const double s = cross(p_segment.a - p_p, d2) / denominator;
		const double u = cross(p_segment.a - p_p, d1) / denominator;
		if (s >= 0.0 && s <= 1.0 && u >= 0.0 && u <= 1.0) {
			return 0.0;
		}
	}
	return std::min({ distance_to_segment(p_segment, p_p), distance_to_segment(p_segment, p_q),
			distance_to_segment(query, p_segment.a), distance_to_segment(query, p_segment.b) });
}

} // namespace

TEST_CASE("constraint geometry: bad walls are rejected by index with a clear message") {
	std::vector<Segment2> walls = test::perfect_maze(5, 10.0, 1);
	MazeMapping mapping;
	mapping.maze_max = { 50.0, 50.0 };
	std::unique_ptr<ConstraintGeometry> geometry;
	REQUIRE(ConstraintGeometry::build(walls.data(), walls.size(), mapping, BroadPhase::UNIFORM_GRID, geometry));
	const ConstraintGeometry *kept = geometry.get();

	std::vector<Segment2> nan_wall = walls;
	nan_wall[7].b.y = NaN;
	Status status = ConstraintGeometry::build(nan_wall.data(), nan_wall.size(), mapping, BroadPhase::UNIFORM_GRID, geometry);
	CHECK(status.code() == StatusCode::INVALID_ARGUMENT);
	CHECK(mentions(status, "constraint.segments[7].b"));
	CHECK(mentions(status, "not finite"));
	CHECK(geometry.get() == kept); // Untouched on error.

	std::vector<Segment2> point_wall = walls;
	point_wall[12].b = point_wall[12].a;
	status = ConstraintGeometry::build(point_wall.data(), point_wall.size(), mapping, BroadPhase::UNIFORM_GRID, geometry);
	CHECK(status.code() == StatusCode::INVALID_ARGUMENT);
	CHECK(mentions(status, "constraint.segments[12]"));
	CHECK(mentions(status, "degenerate"));
	CHECK(geometry.get() == kept);

	std::vector<Segment2> far_wall = walls;
	far_wall[3].a.x = 1e12;
	status = ConstraintGeometry::build(far_wall.data(), far_wall.size(), mapping, BroadPhase::UNIFORM_GRID, geometry);
	CHECK(status.code() == StatusCode::OUT_OF_RANGE);
	CHECK(mentions(status, "constraint.segments[3].a"));

	status = ConstraintGeometry::build(nullptr, 4, mapping, BroadPhase::UNIFORM_GRID, geometry);
	CHECK(status.code() == StatusCode::INVALID_ARGUMENT);
	CHECK(mentions(status, "constraint.segments"));
	status = ConstraintGeometry::build(walls.data(), MAX_CONSTRAINT_SEGMENTS + 1, mapping, BroadPhase::UNIFORM_GRID,
			geometry);
	CHECK(status.code() == StatusCode::OUT_OF_RANGE);
	CHECK(mentions(status, "count"));

	MazeMapping flat = mapping;
	flat.maze_max.y = 0.0;
	status = ConstraintGeometry::build(walls.data(), walls.size(), flat, BroadPhase::UNIFORM_GRID, geometry);
	CHECK(status.code() == StatusCode::OUT_OF_RANGE);
	CHECK(mentions(status, "mapping.maze_max.y"));
	MazeMapping huge = mapping;
	huge.workspace_half_extent_m = 3.0;
	status = ConstraintGeometry::build(walls.data(), walls.size(), huge, BroadPhase::UNIFORM_GRID, geometry);
	CHECK(mentions(status, "mapping.workspace_half_extent_m"));
	MazeMapping lost = mapping;
	lost.workspace_centre_m.x = NaN;
	status = ConstraintGeometry::build(walls.data(), walls.size(), lost, BroadPhase::UNIFORM_GRID, geometry);
	CHECK(mentions(status, "mapping.workspace_centre_m"));
	CHECK(geometry.get() == kept);

	// No walls at all is a valid (empty) maze.
	CHECK(ConstraintGeometry::build(nullptr, 0, mapping, BroadPhase::UNIFORM_GRID, geometry));
	CHECK(geometry->segment_count() == 0);
}

TEST_CASE("maze mapping: the workspace covers the whole maze, one scale, y flipped") {
	MazeMapping mapping;
	mapping.maze_min = { 100.0, 50.0 };
	mapping.maze_max = { 500.0, 350.0 }; // 400 x 300: diagonal 500.
	mapping.maze_y_down = true;
	mapping.workspace_shape = WorkspaceShape::DISC;
	REQUIRE(validate_maze_mapping(mapping));
	const MazeTransform disc = resolve_maze_mapping(mapping, 0.1); // Device radius 0.1 m.
	CHECK(disc.metres_per_unit == doctest::Approx(0.2 / 500.0));
	// Corners land on the workspace circle; the centre on the workspace centre.
	for (const Vec2 corner : { Vec2{ 100.0, 50.0 }, Vec2{ 500.0, 50.0 }, Vec2{ 100.0, 350.0 }, Vec2{ 500.0, 350.0 } }) {
		CHECK(length(disc.to_device(corner)) == doctest::Approx(0.1));
	}
	CHECK(length(disc.to_device({ 300.0, 200.0 })) == doctest::Approx(0.0));
	// Maze y grows down, device y up: the top of the maze is up on the device.
	CHECK(disc.to_device({ 300.0, 50.0 }).y > 0.0);
	CHECK(disc.to_device({ 500.0, 200.0 }).x > 0.0);
	// Round trip.
	const Vec2 point{ 123.0, 321.0 };
	const Vec2 back = disc.to_maze(disc.to_device(point));
	CHECK(back.x == doctest::Approx(point.x));
	CHECK(back.y == doctest::Approx(point.y));

	mapping.workspace_shape = WorkspaceShape::SQUARE;
	mapping.workspace_half_extent_m = 0.05;
	mapping.workspace_centre_m = { 0.01, -0.02 };
	mapping.maze_y_down = false;
	const MazeTransform square = resolve_maze_mapping(mapping, 0.1);
	CHECK(square.metres_per_unit == doctest::Approx(0.1 / 400.0)); // Longer side spans 2 R.
	CHECK(square.to_device({ 500.0, 200.0 }).x == doctest::Approx(0.06));
	CHECK(square.to_device({ 300.0, 350.0 }).y == doctest::Approx(-0.02 + 0.0375));
}

TEST_CASE("constraint geometry: a closed chain becomes the polygon's edges") {
	const Vec2 triangle[] = { { 0.0, 0.0 }, { 4.0, 0.0 }, { 4.0, 0.0 }, { 0.0, 3.0 } }; // A repeated vertex.
	std::vector<Segment2> walls;
	append_closed_chain(triangle, 4, walls);
	REQUIRE(walls.size() == 3);
	CHECK(walls[0].b == Vec2{ 4.0, 0.0 });
	CHECK(walls[2].a == Vec2{ 0.0, 3.0 });
	CHECK(walls[2].b == Vec2{ 0.0, 0.0 }); // Closed.
	append_closed_chain(triangle, 1, walls);
	CHECK(walls.size() == 3);
}

TEST_CASE("broad phase: the grid reports every nearby wall exactly once") {
	std::mt19937 random(99);
	std::uniform_real_distribution<double> unit(0.0, 1.0);
	// Mostly short walls, some long diagonals across everything, some on cell boundaries.
	std::vector<Segment2> walls;
	for (int s = 0; s < 3000; ++s) {
		const Vec2 a{ 1000.0 * unit(random), 1000.0 * unit(random) };
		const double reach = s % 100 == 0 ? 800.0 : 15.0;
		const double angle = 6.283185307179586 * unit(random);
		walls.push_back({ a, a + Vec2{ std::cos(angle), std::sin(angle) } * (1.0 + reach * unit(random)) });
	}
	const std::vector<Segment2> maze = test::perfect_maze(20, 10.0, 4);
	walls.insert(walls.end(), maze.begin(), maze.end());
	MazeMapping mapping;
	mapping.maze_max = { 1000.0, 1000.0 };
	std::unique_ptr<ConstraintGeometry> geometry;
	REQUIRE(ConstraintGeometry::build(walls.data(), walls.size(), mapping, BroadPhase::UNIFORM_GRID, geometry));
	CHECK(geometry->grid_columns() > 1);
	CHECK(geometry->grid_rows() > 1);
	std::vector<int> visits(walls.size());
	int missed = 0;
	int repeated = 0;
	size_t visited_total = 0;
	size_t near_total = 0;
	for (int q = 0; q < 2000; ++q) {
		// Queries inside, across and outside the grid; short moves, long jumps, points.
		const Vec2 from{ 1200.0 * unit(random) - 100.0, 1200.0 * unit(random) - 100.0 };
		const double jump = q % 10 == 0 ? 600.0 : (q % 10 == 1 ? 0.0 : 8.0);
		const Vec2 to = from + Vec2{ unit(random) - 0.5, unit(random) - 0.5 } * (2.0 * jump);
		const double inflate = 0.1 + 6.0 * unit(random);
		std::fill(visits.begin(), visits.end(), 0);
		geometry->for_each_near(from, to, inflate, [&](size_t p_index) { ++visits[p_index]; });
		for (size_t s = 0; s < walls.size(); ++s) {
			repeated += visits[s] > 1 ? 1 : 0;
			visited_total += visits[s] > 0 ? 1 : 0;
			if (segment_distance(from, to, walls[s]) <= inflate) {
				++near_total;
				missed += visits[s] == 0 ? 1 : 0;
			}
		}
	}
	CHECK(missed == 0);
	CHECK(repeated == 0);
	CHECK(near_total > 1000);
	// And it is a broad phase: far fewer visits than walls x queries.
	CHECK(visited_total < walls.size() * 2000 / 20);
	MESSAGE("grid ", geometry->grid_columns(), " x ", geometry->grid_rows(), ", cell ", geometry->cell_size(), ", ",
			geometry->grid_entries(), " entries for ", walls.size(), " walls; visited ", visited_total, ", near ",
			near_total);
}
