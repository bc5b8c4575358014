// The constraint-based renderer inside the engine: step() renders exactly what the proxy
// alone computes (1 kHz and 50 Hz variants), the safety stage still applies, modes switch,
// rejected geometry keeps the previous walls, and walls can be swapped while the servo
// thread runs.

#include "core/base/realtime.h"
#include "core/servo/telemetry.h"
#include "renderers/constraint/constraint_port.h"
#include "renderers/constraint/constraint_renderer.h"
#include "renderers/movement/force_model.h"
#include "system/haptics_system.h"
#include "system_config.h"
#include "test_proxy_geometry.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <numbers>
#include <vector>

using namespace haptics;

namespace {

constexpr double DT = 0.001;
constexpr double NaN = std::numeric_limits<double>::quiet_NaN();

// 9 x 9 cells of 20 units: 100 walls in [0, 180]^2; the centre (90, 90) is a cell centre.
const std::vector<Segment2> &maze() {
	static const std::vector<Segment2> walls = test::perfect_maze(9, 20.0, 77);
	return walls;
}

MazeMapping maze_mapping() {
	MazeMapping mapping;
	mapping.maze_min = { 0.0, 0.0 };
	mapping.maze_max = { 180.0, 180.0 };
	mapping.maze_y_down = true;
	mapping.workspace_half_extent_m = 0.08;
	return mapping;
}

// The engine's constraint renderer, as the game reaches it.
ConstraintPort maze_port(HapticsSystem &r_system) {
	return ConstraintPort(r_system.renderers().constraint.channels);
}

ProxyState proxy_state(HapticsSystem &r_system) {
	return maze_port(r_system).state();
}

ConstraintConfig constraint_config(ProxyUpdate p_update) {
	ConstraintConfig config;
	// Low enough that the 3.3 N limit is never reached here: the hand is at most 0.14 m from
	// the proxy.
	config.stiffness_n_per_m = 20.0;
	config.proxy_radius = 4.0;
	config.update = p_update;
	return config;
}

// Rigid hand (the stylus is exactly where the test puts it), no ramp, no slew limit.
void set_up(HapticsSystem &r_system, ProxyUpdate p_update) {
	SimulatedDeviceConfig device;
	device.rigid_hand = true;
	REQUIRE(r_system.open_simulated_device(device));
	SafetyConfig safety;
	safety.startup_ramp_s = 0.0;
	safety.slew_rate_n_per_s = 0.0;
	REQUIRE(reconfigure(r_system, [&](RenderConfig &c) { c.servo.safety = safety; }));
	REQUIRE(reconfigure(r_system, [&](RenderConfig &c) { c.constraint = constraint_config(p_update); }));
	REQUIRE(maze_port(r_system).set_geometry(maze().data(), maze().size(), maze_mapping()));
	REQUIRE(reconfigure(r_system, [](RenderConfig &c) { c.servo.render_mode = RenderMode::CONSTRAINT; }));
}

Vec3 hand_path(int p_tick) {
	const double t = p_tick * DT;
	return { 0.05 * std::sin(2.0 * std::numbers::pi * 0.7 * t), 0.05 * std::sin(2.0 * std::numbers::pi * 1.1 * t + 0.3), 0.0 };
}

// Runs the engine and a lone renderer side by side over the same device positions.
void compare_with_proxy_alone(ProxyUpdate p_update) {
	HapticsSystem system;
	set_up(system, p_update);
	std::unique_ptr<ConstraintGeometry> geometry;
	REQUIRE(ConstraintGeometry::build(maze().data(), maze().size(), maze_mapping(), BroadPhase::UNIFORM_GRID, geometry));
	ConstraintSolver alone;
	alone.configure(constraint_config(p_update));
	int differences = 0;
	int pushing = 0;
	int proxy_moves_between_frames = 0;
	uint64_t frames = 0;
	Vec2 previous_proxy;
	for (int k = 0; k < 3000; ++k) {
		REQUIRE(system.set_hand_target(hand_path(k)));
		const bool frame = k % 20 == 0; // The game's 50 Hz.
		if (frame) {
			REQUIRE(system.submit_frame(Frame{}));
			++frames;
		}
		REQUIRE(system.step(DT));
		const ServoOutput out = system.output();
		const ProxyState proxy = proxy_state(system);
		const ConstraintOutput expected =
				alone.render(geometry.get(), 1, out.position_m, 0.1, p_update == ProxyUpdate::SERVO || frame);
		REQUIRE(expected.placed);
		differences += out.forces.parts[WALL_FORCE] == expected.force && out.forces.total == expected.force &&
						proxy.proxy == expected.proxy && proxy.goal == expected.goal &&
						proxy.constraints == expected.active_constraints
				? 0
				: 1;
		pushing += length(expected.force) > 0.05 ? 1 : 0;
		if (!frame && k > 0) {
			proxy_moves_between_frames += proxy.proxy == previous_proxy ? 0 : 1;
		}
		previous_proxy = proxy.proxy;
		CHECK((out.flags & TELEMETRY_FLAG_CONSTRAINT_MODE) != 0);
		CHECK(((out.flags & TELEMETRY_FLAG_PROXY_CONTACT) != 0) == (expected.active_constraints > 0));
	}
	CHECK(differences == 0);
	CHECK(pushing > 300); // The path runs into walls; the comparison is not of zeros.
	CHECK(system.output().render_mode == RenderMode::CONSTRAINT);
	const ProxyState proxy = proxy_state(system);
	CHECK(proxy.placed);
	if (p_update == ProxyUpdate::SERVO) {
		CHECK(proxy.updates == 3000);
		CHECK(proxy_moves_between_frames > 1000);
	} else {
		CHECK(proxy.updates == frames);
		CHECK(proxy_moves_between_frames == 0); // Held between frames...
	}
	CHECK(system.stats().non_finite_ticks == 0);
}

} // namespace

TEST_CASE("constraint system: step() renders what the proxy alone computes, 1 kHz proxy") {
	compare_with_proxy_alone(ProxyUpdate::SERVO);
}

TEST_CASE("constraint system: the paper's 50 Hz variant moves the proxy only on frames") {
	compare_with_proxy_alone(ProxyUpdate::FRAME);
}

TEST_CASE("constraint system: force is k_c (proxy - device), normal to the wall, in newtons") {
	HapticsSystem system;
	set_up(system, ProxyUpdate::SERVO);
	// One vertical wall at maze x = 120 across the whole maze; the device pushes to maze
	// x = 130, y = 90 (10 units into it) from the left.
	const Segment2 wall{ { 120.0, 0.0 }, { 120.0, 180.0 } };
	REQUIRE(maze_port(system).set_geometry(&wall, 1, maze_mapping()));
	const double metres_per_unit = 0.16 / (180.0 * std::sqrt(2.0));
	for (double x = 90.0; x <= 130.0; x += 1.0) {
		REQUIRE(system.set_hand_target({ (x - 90.0) * metres_per_unit, 0.0, 0.0 }));
		REQUIRE(system.submit_frame(Frame{}));
		REQUIRE(system.step(DT));
	}
	const ForceComponents f = system.forces();
	const double penetration_m = (130.0 - (120.0 - 4.0)) * metres_per_unit; // Past proxy surface.
	CHECK(proxy_state(system).proxy.x == doctest::Approx(116.0).epsilon(1e-6));
	CHECK(proxy_state(system).proxy.y == doctest::Approx(90.0));
	CHECK(f.parts[WALL_FORCE].x == doctest::Approx(-20.0 * penetration_m).epsilon(1e-6));
	CHECK(f.parts[WALL_FORCE].y == doctest::Approx(0.0).epsilon(1e-9));
	CHECK(f.parts[WALL_FORCE].z == 0.0);
	for (size_t part = WALL_FORCE + 1; part < MAX_FORCE_PARTS; ++part) {
		CHECK(f.parts[part] == Vec3{}); // Only the walls push.
	}
	CHECK(f.total == f.parts[WALL_FORCE]);
	CHECK(proxy_state(system).constraints == 1);
}

TEST_CASE("constraint system: clamp, start-up ramp and watchdog still apply") {
	HapticsSystem system;
	set_up(system, ProxyUpdate::SERVO);
	ConstraintConfig stiff = constraint_config(ProxyUpdate::SERVO);
	stiff.stiffness_n_per_m = 5000.0;
	REQUIRE(reconfigure(system, [&](RenderConfig &c) { c.constraint = stiff; }));
	SafetyConfig safety;
	safety.slew_rate_n_per_s = 0.0;
	safety.startup_ramp_s = 0.01;
	REQUIRE(reconfigure(system, [&](RenderConfig &c) { c.servo.safety = safety; }));
	const Segment2 wall{ { 120.0, 0.0 }, { 120.0, 180.0 } };
	REQUIRE(maze_port(system).set_geometry(&wall, 1, maze_mapping()));
	REQUIRE(system.set_hand_target({ 0.0, 0.0, 0.0 }));
	REQUIRE(system.submit_frame(Frame{}));
	REQUIRE(system.step(DT)); // Placed at the centre.
	REQUIRE(system.set_hand_target({ 0.03, 0.0, 0.0 })); // Deep into the wall in one tick.
	REQUIRE(system.step(DT));
	const ServoOutput ramping = system.output();
	CHECK(ramping.ramp_gain == doctest::Approx(0.2));
	// Ramp first, then the clamp (safety.h): 0.2 of the proxy's force, at most 3.3 N.
	CHECK(length(ramping.forces.total) == doctest::Approx(std::min(3.3, 0.2 * length(ramping.forces.parts[WALL_FORCE]))));
	for (int k = 0; k < 20; ++k) {
		REQUIRE(system.step(DT));
	}
	ServoOutput out = system.output();
	CHECK(length(out.forces.parts[WALL_FORCE]) > 3.3); // What the proxy asks for...
	CHECK(length(out.forces.total) == doctest::Approx(3.3)); // ...and what the device gets.
	CHECK(out.forces.total.x < 0.0);
	CHECK((out.flags & TELEMETRY_FLAG_CLAMPED) != 0);
	CHECK(proxy_state(system).proxy.x < 120.0 - 4.0 + 1e-9);
	// No frames for longer than the watchdog's timeout + fade: the force fades out.
	for (int k = 0; k < 200; ++k) {
		REQUIRE(system.step(DT));
	}
	out = system.output();
	CHECK((out.flags & TELEMETRY_FLAG_WATCHDOG) != 0);
	CHECK(out.forces.total == Vec3{});
	CHECK(length(out.forces.parts[WALL_FORCE]) > 3.3); // Still computed, not rendered.
}

TEST_CASE("constraint system: switching modes hands over between the renderers") {
	HapticsSystem system;
	set_up(system, ProxyUpdate::SERVO);
	REQUIRE(reconfigure(system, [](RenderConfig &c) { c.movement.smoothing = SmoothingConfig{ false, 13.0 }; }));
	REQUIRE(reconfigure(system, [](RenderConfig &c) { c.servo.render_mode = RenderMode::MOVEMENT; }));
	const Segment2 wall{ { 120.0, 0.0 }, { 120.0, 180.0 } };
	REQUIRE(maze_port(system).set_geometry(&wall, 1, maze_mapping()));
	Frame floor;
	add_contact(floor, { 0.0, 1.0, 0.0 });
	const double metres_per_unit = 0.16 / (180.0 * std::sqrt(2.0));
	const Vec3 on_the_wall{ (121.0 - 90.0) * metres_per_unit, -0.05, 0.0 }; // Within r of it.
	REQUIRE(system.set_hand_target(on_the_wall));
	REQUIRE(system.submit_frame(floor));
	REQUIRE(system.step(DT));
	const Vec3 movement = system.forces().parts[NORMAL_FORCE];
	CHECK(movement.y > 0.0); // The movement model's floor force.
	CHECK(system.config().servo.render_mode == RenderMode::MOVEMENT);
	CHECK_FALSE(proxy_state(system).placed);

	REQUIRE(reconfigure(system, [](RenderConfig &c) { c.servo.render_mode = RenderMode::CONSTRAINT; }));
	REQUIRE(system.step(DT)); // The device maps inside the wall: the proxy waits.
	CHECK(system.config().servo.render_mode == RenderMode::CONSTRAINT);
	CHECK_FALSE(proxy_state(system).placed);
	CHECK(system.forces().total == Vec3{});
	CHECK(proxy_state(system).proxy == proxy_state(system).goal);
	REQUIRE(system.set_hand_target({ 0.0, 0.0, 0.0 }));
	REQUIRE(system.step(DT)); // Free space: placed, no force.
	CHECK(proxy_state(system).placed);
	REQUIRE(system.set_hand_target({ 0.03, -0.05, 0.0 }));
	REQUIRE(system.step(DT));
	CHECK(system.forces().parts[WALL_FORCE].x < 0.0); // Now the wall pushes back, floor contact ignored.
	CHECK(proxy_state(system).proxy.x == doctest::Approx(116.0).epsilon(1e-6));
	REQUIRE(system.set_hand_target(on_the_wall));
	CHECK(system.forces().parts[WALL_FORCE].y == doctest::Approx(0.0).epsilon(1e-9));

	REQUIRE(reconfigure(system, [](RenderConfig &c) { c.servo.render_mode = RenderMode::MOVEMENT; }));
	REQUIRE(system.step(DT));
	CHECK(system.forces().parts[NORMAL_FORCE] == movement);
	CHECK(reconfigure(system, [](RenderConfig &c) { c.servo.render_mode = 9; }).code() == StatusCode::INVALID_ARGUMENT);
	CHECK(system.config().servo.render_mode == RenderMode::MOVEMENT);
}

TEST_CASE("constraint system: rejected geometry or config names the problem and keeps the previous one") {
	HapticsSystem system;
	set_up(system, ProxyUpdate::SERVO);
	const Segment2 wall{ { 120.0, 0.0 }, { 120.0, 180.0 } };
	REQUIRE(maze_port(system).set_geometry(&wall, 1, maze_mapping()));
	REQUIRE(system.set_hand_target({ 0.0, 0.0, 0.0 }));
	REQUIRE(system.submit_frame(Frame{}));
	REQUIRE(system.step(DT));
	REQUIRE(system.set_hand_target({ 0.03, 0.0, 0.0 }));
	REQUIRE(system.step(DT));
	const Vec3 held = system.forces().parts[WALL_FORCE];
	const Vec2 proxy = proxy_state(system).proxy;
	REQUIRE(held.x < 0.0);

	std::vector<Segment2> bad(5, wall);
	bad[3].a.x = NaN;
	Status status = maze_port(system).set_geometry(bad.data(), bad.size(), maze_mapping());
	CHECK(status.code() == StatusCode::INVALID_ARGUMENT);
	CHECK(std::strstr(status.message(), "constraint.segments[3].a") != nullptr);
	bad[3] = Segment2{ { 5.0, 5.0 }, { 5.0, 5.0 } };
	status = maze_port(system).set_geometry(bad.data(), bad.size(), maze_mapping());
	CHECK(std::strstr(status.message(), "constraint.segments[3]: degenerate") != nullptr);
	ConstraintConfig wild = constraint_config(ProxyUpdate::SERVO);
	wild.proxy_radius = 0.0;
	status = reconfigure(system, [&](RenderConfig &c) { c.constraint = wild; });
	CHECK(std::strstr(status.message(), "HapticConstraintSettings.proxy_radius") != nullptr);
	wild = constraint_config(ProxyUpdate::SERVO);
	wild.stiffness_n_per_m = NaN;
	CHECK(std::strstr(reconfigure(system, [&](RenderConfig &c) { c.constraint = wild; }).message(), "HapticConstraintSettings.stiffness_n_per_m") != nullptr);
	wild = constraint_config(ProxyUpdate::SERVO);
	wild.max_iterations = 0;
	CHECK(std::strstr(reconfigure(system, [&](RenderConfig &c) { c.constraint = wild; }).message(), "HapticConstraintSettings.max_iterations") != nullptr);
	for (int k = 0; k < 10; ++k) {
		REQUIRE(system.step(DT));
	}
	CHECK(system.forces().parts[WALL_FORCE] == held); // The same wall, the same proxy, the same config.
	CHECK(proxy_state(system).proxy == proxy);
	CHECK(system.config().constraint.proxy_radius == 4.0);
}

TEST_CASE("constraint system: walls swapped while the servo thread runs") {
	HapticsSystem system;
	SimulatedDeviceConfig device;
	device.rigid_hand = true;
	REQUIRE(system.open_simulated_device(device));
	REQUIRE(reconfigure(system, [&](RenderConfig &c) { c.constraint = constraint_config(ProxyUpdate::SERVO); }));
	REQUIRE(reconfigure(system, [](RenderConfig &c) { c.servo.render_mode = RenderMode::CONSTRAINT; }));
	ServoOptions options;
	options.realtime.priority = 0;
	REQUIRE(system.start(options));
	// Wait until a condition holds, feeding frames like the game does (which also frees
	// the walls the servo let go of).
	const auto wait_for = [&](auto p_condition) {
		for (int k = 0; k < 2000; ++k) {
			system.submit_frame(Frame{});
			if (p_condition(system.output(), proxy_state(system))) {
				return true;
			}
			sleep_for_ns(1'000'000);
		}
		return false;
	};
	// Decoys: the maze squeezed into the band y in [0, 36], away from the proxy's row y = 90.
	std::vector<Segment2> decoys = maze();
	for (Segment2 &segment : decoys) {
		segment.a.y *= 0.2;
		segment.b.y *= 0.2;
	}
	int swaps = 0;
	uint64_t generation = 0;
	for (int round = 0; round < 10; ++round) {
		// A burst of publications the servo cannot all pick up: the unseen ones are freed by
		// the game thread, the last one wins. Each round's wall stands 2 units further right,
		// so the proxy can only reach its new place if the swap really happened.
		REQUIRE(system.set_hand_target({ 0.0, 0.0, 0.0 }));
		for (int burst = 0; burst < 5; ++burst) {
			REQUIRE(maze_port(system).set_geometry(decoys.data(), decoys.size(), maze_mapping()));
		}
		const double x = 110.0 + 2.0 * round;
		const Segment2 wall{ { x, 0.0 }, { x, 180.0 } };
		REQUIRE(maze_port(system).set_geometry(&wall, 1, maze_mapping()));
		REQUIRE(wait_for([&](const ServoOutput &, const ProxyState &p_proxy) {
			return p_proxy.geometry_segments == 1 && p_proxy.geometry_generation > generation && p_proxy.placed &&
					length(p_proxy.proxy - Vec2{ 90.0, 90.0 }) < 1e-9;
		}));
		generation = proxy_state(system).geometry_generation;
		REQUIRE(system.set_hand_target({ 0.03, 0.0, 0.0 })); // Maze x = 137.7, past the wall.
		const bool held = wait_for([x](const ServoOutput &p_out, const ProxyState &p_proxy) {
			return p_proxy.placed && p_proxy.constraints == 1 && p_out.forces.parts[WALL_FORCE].x < 0.0 &&
					std::abs(p_proxy.proxy.x - (x - 4.0)) < 1e-4; // Less the skin.
		});
		swaps += held ? 1 : 0;
	}
	system.stop();
	CHECK(swaps == 10);
	CHECK(system.stats().non_finite_ticks == 0);
}
