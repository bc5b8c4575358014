// The finite proxy alone: continuous collision of the disc, the active-constraint solver
// (slide, corner, dead end), no tunnelling through thin walls, and a long run through a
// 10 000-wall maze.

#include "renderers/constraint/constraint_geometry.h"
#include "renderers/constraint/constraint_renderer.h"
#include "renderers/constraint/finite_proxy.h"
#include "renderers/constraint/swept_disc.h"
#include "test_proxy_geometry.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <random>
#include <vector>

using namespace haptics;

namespace {

constexpr uint32_t ITERATIONS = 6;

std::unique_ptr<ConstraintGeometry> make_geometry(const std::vector<Segment2> &p_walls,
		BroadPhase p_broad_phase = BroadPhase::UNIFORM_GRID) {
	MazeMapping mapping;
	mapping.maze_min = { -2000.0, -2000.0 };
	mapping.maze_max = { 2000.0, 2000.0 };
	std::unique_ptr<ConstraintGeometry> geometry;
	const Status status = ConstraintGeometry::build(p_walls.data(), p_walls.size(), mapping, p_broad_phase, geometry);
	REQUIRE_MESSAGE(status, status.message());
	return geometry;
}

double min_distance(const std::vector<Segment2> &p_walls, const Vec2 &p_point) {
	double best = INFINITY;
	for (const Segment2 &wall : p_walls) {
		best = std::min(best, distance_to_segment(wall, p_point));
	}
	return best;
}

// Holds the goal (with some noise) for p_ticks and returns the largest move of the proxy
// between two consecutive updates after the first p_settle ticks.
double hold(FiniteProxy &r_proxy, const ConstraintGeometry &p_geometry, const Vec2 &p_goal, double p_noise,
		double p_radius, int p_ticks, int p_settle = 20) {
	std::mt19937 random(11);
	std::uniform_real_distribution<double> noise(-p_noise, p_noise);
	double largest = 0.0;
	for (int k = 0; k < p_ticks; ++k) {
		const Vec2 before = r_proxy.position();
		r_proxy.update(p_geometry, p_goal + Vec2{ noise(random), noise(random) }, p_radius, ITERATIONS);
		if (k >= p_settle) {
			largest = std::max(largest, length(r_proxy.position() - before));
		}
	}
	return largest;
}

} // namespace

TEST_CASE("swept disc: flat side, round end cap, touching, leaving") {
	const Segment2 wall{ { -5.0, 0.0 }, { 5.0, 0.0 } };
	DiscHit hit;
	// Straight down onto the flat side: touches when the centre is 1 above, half-way.
	REQUIRE(sweep_disc_segment({ 0.0, 3.0 }, { 0.0, -4.0 }, 1.0, wall, 1e-6, hit));
	CHECK(hit.t == doctest::Approx(0.5));
	CHECK(hit.normal.x == doctest::Approx(0.0));
	CHECK(hit.normal.y == doctest::Approx(1.0));
	// From below: the normal points down, toward the disc.
	REQUIRE(sweep_disc_segment({ 1.0, -3.0 }, { 0.0, 4.0 }, 1.0, wall, 1e-6, hit));
	CHECK(hit.normal.y == doctest::Approx(-1.0));
	// Past the end but within the radius: the round cap at (5, 0) is hit.
	REQUIRE(sweep_disc_segment({ 5.5, 3.0 }, { 0.0, -6.0 }, 1.0, wall, 1e-6, hit));
	CHECK(hit.t == doctest::Approx((3.0 - std::sqrt(0.75)) / 6.0));
	CHECK(hit.normal.x == doctest::Approx(0.5));
	CHECK(hit.normal.y == doctest::Approx(std::sqrt(0.75)));
	// Farther than the radius past the end: no hit.
	CHECK_FALSE(sweep_disc_segment({ 6.5, 3.0 }, { 0.0, -6.0 }, 1.0, wall, 1e-6, hit));
	// A jump far past the wall in one step is still a hit (no tunnelling).
	REQUIRE(sweep_disc_segment({ 0.0, 3.0 }, { 0.0, -1e6 }, 1.0, wall, 1e-6, hit));
	CHECK(hit.t == doctest::Approx(2.0 / 1e6));
	// Too short a step to reach it: no hit.
	CHECK_FALSE(sweep_disc_segment({ 0.0, 3.0 }, { 0.0, -1.5 }, 1.0, wall, 1e-6, hit));
	// Resting on it: into it is a hit at t = 0, along or away from it is not.
	REQUIRE(sweep_disc_segment({ 0.0, 1.0 }, { 0.3, -0.2 }, 1.0, wall, 1e-6, hit));
	CHECK(hit.t == 0.0);
	CHECK_FALSE(sweep_disc_segment({ 0.0, 1.0 }, { 3.0, 0.0 }, 1.0, wall, 1e-6, hit));
	CHECK_FALSE(sweep_disc_segment({ 0.0, 1.0 }, { 0.0, 2.0 }, 1.0, wall, 1e-6, hit));
	// Started inside (never happens to the proxy, but a wall may be loaded onto it): it
	// may leave, it may not go deeper.
	CHECK_FALSE(sweep_disc_segment({ 0.0, 0.5 }, { 0.0, 2.0 }, 1.0, wall, 1e-6, hit));
	CHECK(sweep_disc_segment({ 0.0, 0.5 }, { 0.0, -0.2 }, 1.0, wall, 1e-6, hit));
}

TEST_CASE("proxy solver: nearest feasible point for 1, 2 and 3 constraints") {
	const ProxyConstraint floor{ { 0.0, 1.0 }, 1.0 }; // y >= 1
	const ProxyConstraint wall{ { 1.0, 0.0 }, 1.0 }; // x >= 1
	const ProxyConstraint slope{ Vec2{ -1.0, 1.0 } / std::sqrt(2.0), 0.0 }; // y >= x
	const ProxyConstraint one[] = { floor };
	CHECK(project_onto_constraints({ 5.0, -3.0 }, one, 1, { 0.0, 2.0 }, 1e-9) == Vec2{ 5.0, 1.0 });
	CHECK(project_onto_constraints({ 5.0, 3.0 }, one, 1, { 0.0, 2.0 }, 1e-9) == Vec2{ 5.0, 3.0 });
	const ProxyConstraint two[] = { floor, wall };
	const Vec2 corner = project_onto_constraints({ -4.0, -3.0 }, two, 2, { 2.0, 2.0 }, 1e-9);
	CHECK(corner.x == doctest::Approx(1.0));
	CHECK(corner.y == doctest::Approx(1.0));
	const Vec2 slide = project_onto_constraints({ -4.0, 7.0 }, two, 2, { 2.0, 2.0 }, 1e-9);
	CHECK(slide == Vec2{ 1.0, 7.0 });
	const ProxyConstraint three[] = { floor, wall, slope }; // The wedge x >= 1, y >= x.
	const Vec2 wedge = project_onto_constraints({ 9.0, -9.0 }, three, 3, { 2.0, 3.0 }, 1e-9);
	CHECK(wedge.x == doctest::Approx(1.0));
	CHECK(wedge.y == doctest::Approx(1.0));
	const Vec2 along = project_onto_constraints({ 9.0, 5.0 }, three, 3, { 2.0, 3.0 }, 1e-9);
	CHECK(along.x == doctest::Approx(7.0));
	CHECK(along.y == doctest::Approx(7.0));
}

TEST_CASE("proxy: never crosses a thin wall, however deep or far the device goes") {
	std::mt19937 random(7);
	std::uniform_real_distribution<double> unit(0.0, 1.0);
	int ticks_goal_past_wall = 0;
	int jumps_past_wall = 0;
	double worst = INFINITY; // Smallest (signed distance to the wall's line - radius).
	for (int trial = 0; trial < 200; ++trial) {
		const double angle = 2.0 * std::numbers::pi * unit(random);
		const Vec2 along{ std::cos(angle), std::sin(angle) };
		const Vec2 normal = perpendicular(along);
		const Vec2 centre{ 100.0 * unit(random) - 50.0, 100.0 * unit(random) - 50.0 };
		// One zero-thickness segment, long enough that going around its ends is not possible
		// within the goals below.
		const std::vector<Segment2> walls{ { centre - along * 1000.0, centre + along * 1000.0 } };
		const auto geometry = make_geometry(walls);
		const double radius = 0.5 + 4.5 * unit(random);
		FiniteProxy proxy;
		const Vec2 start = centre + normal * (radius + 0.1 + 20.0 * unit(random)) + along * (100.0 * unit(random) - 50.0);
		REQUIRE(proxy.try_place(*geometry, start, radius));
		Vec2 goal = start;
		for (int k = 0; k < 300; ++k) {
			if (unit(random) < 0.1) { // A jump anywhere, usually deep past the wall.
				goal = centre + along * (200.0 * unit(random) - 100.0) + normal * (400.0 * unit(random) - 300.0);
				jumps_past_wall += dot(goal - centre, normal) < 0.0 ? 1 : 0;
			} else {
				goal += Vec2{ unit(random) - 0.5, unit(random) - 0.5 } * 10.0;
			}
			proxy.update(*geometry, goal, radius, ITERATIONS);
			ticks_goal_past_wall += dot(goal - centre, normal) < 0.0 ? 1 : 0;
			worst = std::min(worst, (dot(proxy.position() - centre, normal) - radius) / radius);
		}
	}
	CHECK(ticks_goal_past_wall > 10000); // The device really was past the wall, often.
	CHECK(jumps_past_wall > 1000);
	CHECK(worst >= -1e-9); // The disc never overlapped the wall, let alone crossed it.
}

TEST_CASE("proxy: a thin polygon (closed chain) is not entered from any side") {
	// A 20 x 0.01 sliver, as a collision polygon's outline.
	const Vec2 outline[] = { { -10.0, -0.005 }, { 10.0, -0.005 }, { 10.0, 0.005 }, { -10.0, 0.005 } };
	std::vector<Segment2> walls;
	append_closed_chain(outline, 4, walls);
	REQUIRE(walls.size() == 4);
	const auto geometry = make_geometry(walls);
	std::mt19937 random(3);
	std::uniform_real_distribution<double> unit(-1.0, 1.0);
	const double radius = 0.7;
	double closest = INFINITY;
	for (int trial = 0; trial < 100; ++trial) {
		FiniteProxy proxy;
		const double side = trial % 2 == 0 ? 1.0 : -1.0;
		REQUIRE(proxy.try_place(*geometry, { 8.0 * unit(random), side * 3.0 }, radius));
		for (int k = 0; k < 200; ++k) {
			// Goals inside the sliver and beyond it, on the other side.
			const Vec2 goal{ 9.0 * unit(random), k % 3 == 0 ? 0.001 * unit(random) : -side * 50.0 * std::abs(unit(random)) };
			proxy.update(*geometry, goal, radius, ITERATIONS);
			CHECK(side * proxy.position().y > 0.0);
			closest = std::min(closest, min_distance(walls, proxy.position()));
		}
	}
	CHECK(closest >= radius * (1.0 - 1e-9));
}

TEST_CASE("proxy: sliding along a wall keeps the tangential motion") {
	const double radius = 1.0;
	SUBCASE("horizontal wall") {
		const std::vector<Segment2> walls{ { { -100.0, 0.0 }, { 100.0, 0.0 } } };
		const auto geometry = make_geometry(walls);
		FiniteProxy proxy;
		REQUIRE(proxy.try_place(*geometry, { -50.0, 5.0 }, radius));
		for (double x = -50.0; x <= 50.0; x += 0.37) {
			proxy.update(*geometry, { x, -3.0 }, radius, ITERATIONS); // 3 units inside the wall.
			CHECK(proxy.position().x == doctest::Approx(x).epsilon(1e-12));
			CHECK(proxy.position().y == doctest::Approx(radius).epsilon(1e-5));
			CHECK(proxy.position().y >= radius);
			CHECK(proxy.active_constraints() == 1);
		}
	}
	SUBCASE("tilted wall, goal moving along it and in and out of it") {
		const Vec2 along = Vec2{ 2.0, 1.0 } / std::sqrt(5.0);
		const Vec2 normal = perpendicular(along);
		const std::vector<Segment2> walls{ { along * -100.0, along * 100.0 } };
		const auto geometry = make_geometry(walls);
		FiniteProxy proxy;
		REQUIRE(proxy.try_place(*geometry, along * -40.0 + normal * 2.0, radius));
		for (int k = 0; k < 400; ++k) {
			const double s = -40.0 + 0.2 * k;
			const double depth = 2.0 + std::sin(0.1 * k); // Always inside the wall.
			proxy.update(*geometry, along * s - normal * depth, radius, ITERATIONS);
			const Vec2 expected = along * s + normal * radius;
			CHECK(length(proxy.position() - expected) < 1e-5);
			CHECK(dot(proxy.position(), normal) >= radius * (1.0 - 1e-12));
		}
	}
}

TEST_CASE("proxy: a 90 degree corner stops it, two constraints, no jitter") {
	const std::vector<Segment2> walls{ { { 0.0, 0.0 }, { 0.0, 50.0 } }, { { 0.0, 0.0 }, { 50.0, 0.0 } } };
	const auto geometry = make_geometry(walls);
	FiniteProxy proxy;
	REQUIRE(proxy.try_place(*geometry, { 10.0, 10.0 }, 1.0));
	const double jitter = hold(proxy, *geometry, { -5.0, -5.0 }, 0.5, 1.0, 1000);
	CHECK(proxy.position().x == doctest::Approx(1.0).epsilon(1e-5));
	CHECK(proxy.position().y == doctest::Approx(1.0).epsilon(1e-5));
	CHECK(min_distance(walls, proxy.position()) >= 1.0);
	CHECK(proxy.active_constraints() == 2);
	CHECK(jitter < 1e-12);
}

TEST_CASE("proxy: an acute corner stops it where the disc touches both walls") {
	const double angle = std::numbers::pi / 6.0; // 30 degrees between the walls.
	const std::vector<Segment2> walls{ { { 0.0, 0.0 }, { 50.0, 0.0 } },
		{ { 0.0, 0.0 }, { 50.0 * std::cos(angle), 50.0 * std::sin(angle) } } };
	const auto geometry = make_geometry(walls);
	const double radius = 1.0;
	const double apex_distance = radius / std::sin(angle / 2.0);
	const Vec2 expected{ apex_distance * std::cos(angle / 2.0), apex_distance * std::sin(angle / 2.0) };
	for (const Vec2 goal : { Vec2{ -20.0, 2.0 }, Vec2{ -5.0, -30.0 }, Vec2{ 1.0, 0.2 } }) {
		CAPTURE(goal.x);
		CAPTURE(goal.y);
		FiniteProxy proxy;
		REQUIRE(proxy.try_place(*geometry, { 30.0, 5.0 }, radius));
		const double jitter = hold(proxy, *geometry, goal, 0.1, radius, 1000);
		CHECK(length(proxy.position() - expected) < 1e-5);
		CHECK(min_distance(walls, proxy.position()) >= radius);
		CHECK(proxy.active_constraints() == 2);
		CHECK(jitter < 1e-12);
	}
}

TEST_CASE("proxy: a three-wall dead end stops it without jitter") {
	const double radius = 1.0;
	SUBCASE("corridor wider than the disc") {
		const std::vector<Segment2> walls{ { { 0.0, 0.0 }, { 20.0, 0.0 } }, { { 0.0, 3.0 }, { 20.0, 3.0 } },
			{ { 0.0, 0.0 }, { 0.0, 3.0 } } };
		const auto geometry = make_geometry(walls);
		const struct {
			Vec2 goal;
			Vec2 stop;
			uint32_t constraints;
		} cases[] = {
			{ { -10.0, 1.5 }, { 1.0, 1.5 }, 1 }, // Against the end: one wall, free to slide.
			{ { -10.0, -10.0 }, { 1.0, 1.0 }, 2 }, // Into the lower corner.
			{ { -10.0, 10.0 }, { 1.0, 2.0 }, 2 }, // Into the upper corner.
		};
		for (const auto &c : cases) {
			FiniteProxy proxy;
			REQUIRE(proxy.try_place(*geometry, { 15.0, 1.5 }, radius));
			const double jitter = hold(proxy, *geometry, c.goal, 0.0, radius, 500);
			CHECK(length(proxy.position() - c.stop) < 1e-5);
			CHECK(proxy.active_constraints() == c.constraints);
			CHECK(jitter < 1e-12);
		}
		// A noisy hand pushing around the end: always inside, never in a wall.
		FiniteProxy proxy;
		REQUIRE(proxy.try_place(*geometry, { 15.0, 1.5 }, radius));
		std::mt19937 random(5);
		std::uniform_real_distribution<double> unit(-1.0, 1.0);
		for (int k = 0; k < 2000; ++k) {
			proxy.update(*geometry, { -10.0 + 5.0 * unit(random), 1.5 + 8.0 * unit(random) }, radius, ITERATIONS);
			CHECK(min_distance(walls, proxy.position()) >= radius * (1.0 - 1e-9));
			CHECK(proxy.position().x > 0.0);
		}
	}
	SUBCASE("dead end barely wider than the disc: three walls touch it at once") {
		const std::vector<Segment2> walls{ { { 0.0, 0.0 }, { 20.0, 0.0 } }, { { 0.0, 2.001 }, { 20.0, 2.001 } },
			{ { 0.0, 0.0 }, { 0.0, 2.001 } } };
		const auto geometry = make_geometry(walls);
		FiniteProxy proxy;
		REQUIRE(proxy.try_place(*geometry, { 15.0, 1.0005 }, radius));
		const double jitter = hold(proxy, *geometry, { -10.0, 1.0 }, 3.0, radius, 2000);
		CHECK(proxy.position().x == doctest::Approx(1.0).epsilon(1e-5));
		CHECK(min_distance(walls, proxy.position()) >= radius * (1.0 - 1e-9));
		CHECK(jitter < 1e-2); // It may slide across the 0.001 of play, nothing more.
	}
	SUBCASE("three walls meeting at one point") {
		// A V with a wall down its middle: two 45 degree wedges sharing the vertex.
		const std::vector<Segment2> walls{ { { 0.0, 0.0 }, { -20.0, 20.0 } }, { { 0.0, 0.0 }, { 20.0, 20.0 } },
			{ { 0.0, 0.0 }, { 0.0, 20.0 } } };
		const auto geometry = make_geometry(walls);
		FiniteProxy proxy;
		REQUIRE(proxy.try_place(*geometry, { -5.0, 15.0 }, radius));
		const double jitter = hold(proxy, *geometry, { 3.0, -30.0 }, 0.5, radius, 1000);
		const double apex_distance = radius / std::sin(std::numbers::pi / 8.0);
		const Vec2 expected{ -apex_distance * std::sin(std::numbers::pi / 8.0),
			apex_distance * std::cos(std::numbers::pi / 8.0) };
		CHECK(length(proxy.position() - expected) < 1e-5);
		CHECK(min_distance(walls, proxy.position()) >= radius);
		CHECK(proxy.active_constraints() == 2);
		CHECK(jitter < 1e-12);
	}
}

TEST_CASE("proxy: stable at 1 kHz for 5 s through a 10 000-wall maze (grid == brute force)") {
	// 99 x 99 cells of 10 units: 10 000 segments; corridors 10 wide, disc radius 3.
	const std::vector<Segment2> walls = test::perfect_maze(99, 10.0, 2024);
	REQUIRE(walls.size() == 10000);
	MazeMapping mapping;
	mapping.maze_min = { 0.0, 0.0 };
	mapping.maze_max = { 990.0, 990.0 };
	mapping.workspace_half_extent_m = 0.1;
	std::unique_ptr<ConstraintGeometry> grid;
	std::unique_ptr<ConstraintGeometry> brute;
	REQUIRE(ConstraintGeometry::build(walls.data(), walls.size(), mapping, BroadPhase::UNIFORM_GRID, grid));
	REQUIRE(ConstraintGeometry::build(walls.data(), walls.size(), mapping, BroadPhase::BRUTE_FORCE, brute));
	ConstraintConfig config;
	config.stiffness_n_per_m = 300.0;
	config.proxy_radius = 3.0;
	ConstraintSolver fast;
	ConstraintSolver reference;
	fast.configure(config);
	reference.configure(config);
	const double radius = config.proxy_radius;
	double worst_penetration = -INFINITY;
	double largest_force = 0.0;
	int ticks_in_contact = 0;
	int mismatches = 0;
	bool finite = true;
	for (int k = 0; k < 5000; ++k) {
		const double t = k * 0.001;
		// Up to ~0.2 m/s: about 1.5 maze units (a seventh of a corridor) per tick.
		const Vec3 device{ 0.065 * std::sin(2.0 * std::numbers::pi * 0.37 * t),
			0.065 * std::sin(2.0 * std::numbers::pi * 0.53 * t + 0.4), 0.0 };
		const ConstraintOutput out = fast.render(grid.get(), 1, device, 0.1, true);
		const ConstraintOutput ref = reference.render(brute.get(), 1, device, 0.1, true);
		REQUIRE(out.placed);
		mismatches += out.proxy == ref.proxy ? 0 : 1;
		worst_penetration = std::max(worst_penetration, radius - min_distance(walls, out.proxy));
		finite = finite && is_finite(out.force);
		largest_force = std::max(largest_force, length(out.force));
		ticks_in_contact += out.active_constraints > 0 ? 1 : 0;
	}
	CHECK(mismatches == 0);
	CHECK(worst_penetration <= 1e-9 * radius);
	CHECK(finite);
	// Bounded by k_c times the workspace diameter, and in fact by how far a hand gets into a
	// wall along this path.
	CHECK(largest_force < config.stiffness_n_per_m * 0.2);
	CHECK(ticks_in_contact > 1000); // The path really runs into walls.
	MESSAGE("10k maze: worst penetration ", worst_penetration / radius, " r, largest force ", largest_force,
			" N, in contact ", ticks_in_contact, " of 5000 ticks");
}
