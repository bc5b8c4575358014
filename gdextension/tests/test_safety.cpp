// Safety stage: clamp by scaling, slew limit, start-up ramp, watchdog, non-finite guard;
// on the stage itself and end to end through the engine's manual step.

#include "core/servo/safety.h"
#include "system/haptics_system.h"
#include "system_config.h"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>

using namespace haptics;

namespace {

constexpr double DT = 0.001;

SafetyConfig plain_safety() {
	SafetyConfig config;
	config.startup_ramp_s = 0.0;
	config.slew_rate_n_per_s = 0.0;
	return config;
}

// An engine with a rigid-hand simulated device pressing into a wall on its right with a
// steady 2 N (k = 4, i = 0.5), smoothing off so every number is exact.
void set_up_wall(HapticsSystem &r_system, const SafetyConfig &p_safety) {
	SimulatedDeviceConfig device;
	device.rigid_hand = true;
	REQUIRE(r_system.open_simulated_device(device));
	REQUIRE(r_system.set_hand_target({ 0.05, 0.0, 0.0 }));
	ForceModelConfig model;
	model.default_contact = ContactMaterial{ 4.0, 0.0 };
	REQUIRE(reconfigure(r_system, [&](RenderConfig &c) {
		c.movement.force_model = model;
		c.servo.input.dead_zone = 0.0;
	}));
	REQUIRE(reconfigure(r_system, [](RenderConfig &c) { c.movement.smoothing = SmoothingConfig{ false, 13.0 }; }));
	REQUIRE(reconfigure(r_system, [&](RenderConfig &c) { c.servo.safety = p_safety; }));
}

Frame wall_frame() {
	Frame frame;
	add_contact(frame, { -1.0, 0.0, 0.0 });
	return frame;
}

} // namespace

TEST_CASE("clamp: scales the vector to the limit and keeps its direction") {
	bool clamped = false;
	const Vec3 out = clamp_magnitude({ 3.0, 4.0, 0.0 }, 2.5, clamped);
	CHECK(clamped);
	CHECK(out.x == doctest::Approx(1.5));
	CHECK(out.y == doctest::Approx(2.0));
	CHECK(clamp_magnitude({ 0.3, 0.4, 0.0 }, 2.5, clamped) == Vec3{ 0.3, 0.4, 0.0 });
	CHECK_FALSE(clamped);
}

TEST_CASE("safety stage: continuous plus impact clamped to the device limit as one vector") {
	SafetyStage stage;
	stage.configure(plain_safety(), 3.3);
	const SafetyResult result = stage.apply({ 3.0, 4.0, 0.0 }, { 0.0, 0.0, 12.0 }, 0.0, DT);
	CHECK(result.clamped);
	CHECK(length(result.total) == doctest::Approx(3.3));
	const Vec3 expected = Vec3{ 3.0, 4.0, 12.0 } * (3.3 / 13.0);
	CHECK(result.total.x == doctest::Approx(expected.x));
	CHECK(result.total.y == doctest::Approx(expected.y));
	CHECK(result.total.z == doctest::Approx(expected.z));
}

TEST_CASE("safety stage: the configured limit applies only below the device's") {
	SafetyStage stage;
	SafetyConfig config = plain_safety();
	config.max_force_n = 1.0;
	stage.configure(config, 3.3);
	CHECK(stage.max_force_n() == 1.0);
	config.max_force_n = 10.0;
	stage.configure(config, 3.3);
	CHECK(stage.max_force_n() == 3.3);
	config.max_force_n = 0.0;
	stage.configure(config, 8.0);
	CHECK(stage.max_force_n() == 8.0);
}

TEST_CASE("safety stage: slew limit on the continuous force, not on impacts") {
	SafetyStage stage;
	SafetyConfig config = plain_safety();
	config.slew_rate_n_per_s = 100.0; // 0.1 N per 1 ms tick.
	stage.configure(config, 100.0);
	stage.reset();
	for (int k = 1; k <= 25; ++k) {
		const SafetyResult r = stage.apply({ 3.0, 4.0, 0.0 }, {}, 0.0, DT); // |step| = 5 N
		CHECK(length(r.continuous) == doctest::Approx(std::min(5.0, 0.1 * k)));
		CHECK(r.continuous.x * 4.0 == doctest::Approx(r.continuous.y * 3.0)); // Direction kept.
	}
	stage.reset();
	const SafetyResult with_impact = stage.apply({}, { 0.0, 0.0, 2.0 }, 0.0, DT);
	CHECK(with_impact.total.z == doctest::Approx(2.0));
}

TEST_CASE("safety stage: start-up ramp on everything, linear over startup_ramp_s") {
	SafetyStage stage;
	SafetyConfig config = plain_safety();
	config.startup_ramp_s = 0.1;
	stage.configure(config, 100.0);
	stage.reset();
	for (int k = 1; k <= 150; ++k) {
		const SafetyResult r = stage.apply({ 2.0, 0.0, 0.0 }, { 0.0, 1.0, 0.0 }, 0.0, DT);
		const double gain = std::min(1.0, k / 100.0);
		CHECK(r.total.x == doctest::Approx(2.0 * gain));
		CHECK(r.total.y == doctest::Approx(1.0 * gain));
	}
}

TEST_CASE("safety stage: a non-finite input is zeroed and does not poison the next tick") {
	SafetyStage stage;
	stage.configure(SafetyConfig{}, 3.3);
	stage.reset();
	const double nan = std::numeric_limits<double>::quiet_NaN();
	SafetyResult r = stage.apply({ nan, 0.0, 0.0 }, {}, 0.0, DT);
	CHECK(r.non_finite);
	CHECK(r.total == Vec3{});
	r = stage.apply({}, { std::numeric_limits<double>::infinity(), 0.0, 0.0 }, 0.0, DT);
	CHECK(r.non_finite);
	CHECK(r.total == Vec3{});
	r = stage.apply({ 0.1, 0.0, 0.0 }, {}, 0.0, DT);
	CHECK_FALSE(r.non_finite);
	CHECK(is_finite(r.total));
	CHECK(r.total.x > 0.0);
}

TEST_CASE("engine: force clamped to the simulated device's 3.3 N, direction kept") {
	HapticsSystem system;
	set_up_wall(system, plain_safety());
	ForceModelConfig model = system.config().movement.force_model;
	model.default_contact = ContactMaterial{ 20.0, 20.0 }; // 10 N normal, 4 N friction.
	REQUIRE(reconfigure(system, [&](RenderConfig &c) { c.movement.force_model = model; }));
	REQUIRE(system.set_hand_target({ 0.05, 0.02, 0.0 })); // i = (0.5, 0.2, 0)
	REQUIRE(system.submit_frame(wall_frame()));
	REQUIRE(system.step(DT));
	const ForceComponents f = system.forces();
	CHECK(f.continuous.x == doctest::Approx(-10.0));
	CHECK(f.continuous.y == doctest::Approx(-4.0));
	CHECK(length(f.total) == doctest::Approx(3.3));
	CHECK(f.total.x / f.total.y == doctest::Approx(2.5));
	CHECK(system.stats().clamped_ticks == 1);
}

TEST_CASE("engine: no kick when rendering starts or the device is re-opened") {
	HapticsSystem system;
	SafetyConfig safety = plain_safety();
	safety.startup_ramp_s = 0.3;
	safety.slew_rate_n_per_s = 200.0;
	set_up_wall(system, safety);
	for (int pass = 0; pass < 2; ++pass) {
		CAPTURE(pass);
		double previous = 0.0;
		for (int k = 1; k <= 400; ++k) {
			if (k % 20 == 1) {
				REQUIRE(system.submit_frame(wall_frame()));
			}
			REQUIRE(system.step(DT));
			const double magnitude = length(system.forces().total);
			CHECK(magnitude - previous <= 0.2 + 1e-12); // Never more than slew * dt per tick.
			CHECK(magnitude >= previous - 1e-12); // Monotonic: no overshoot on a steady push.
			if (k == 1) {
				CHECK(magnitude < 0.001);
			}
			previous = magnitude;
		}
		CHECK(previous == doctest::Approx(2.0)); // Fully up after the ramp.
		// Re-open (a reconnect): the same again, from zero.
		SimulatedDeviceConfig device;
		device.rigid_hand = true;
		REQUIRE(system.open_simulated_device(device));
		REQUIRE(system.set_hand_target({ 0.05, 0.0, 0.0 }));
	}
}

TEST_CASE("engine: watchdog fades the continuous force within 50 ms of a 100 ms frame gap and recovers") {
	HapticsSystem system;
	set_up_wall(system, plain_safety()); // timeout 0.1 s, fade 0.04 s
	for (int k = 0; k < 200; ++k) { // 200 ms of healthy 50 Hz frames.
		if (k % 20 == 0) {
			REQUIRE(system.submit_frame(wall_frame()));
		}
		REQUIRE(system.step(DT));
	}
	CHECK(system.forces().total.x == doctest::Approx(-2.0));
	// Last frame was picked up at tick 180: from there on, silence.
	for (int since = 20; since <= 160; ++since) { // ms since the last frame
		REQUIRE(system.step(DT));
		const double force = -system.forces().total.x;
		CAPTURE(since);
		if (since <= 99) {
			CHECK(force == doctest::Approx(2.0));
			CHECK_FALSE(system.stats().watchdog_tripped);
		} else if (since == 120) {
			CHECK(force > 0.0); // A fade, not a cut...
			CHECK(force < 2.0);
		} else if (since >= 150) {
			CHECK(force == 0.0); // ... complete within 50 ms of the timeout.
			CHECK(system.stats().watchdog_tripped);
			CHECK(system.forces().continuous.x == doctest::Approx(-2.0)); // The model still runs.
		}
	}
	// Frames return: back to full force, faded in.
	for (int k = 1; k <= 60; ++k) {
		if (k % 20 == 1) {
			REQUIRE(system.submit_frame(wall_frame()));
		}
		REQUIRE(system.step(DT));
		const double force = -system.forces().total.x;
		if (k == 1) {
			CHECK(force < 0.1);
		}
		if (k >= 45) {
			CHECK(force == doctest::Approx(2.0));
		}
	}
	CHECK_FALSE(system.stats().watchdog_tripped);
}

TEST_CASE("engine: the watchdog leaves impacts alone") {
	HapticsSystem system;
	set_up_wall(system, plain_safety());
	for (int k = 0; k < 300; ++k) { // No frame at all: watchdog tripped.
		REQUIRE(system.step(DT));
	}
	CHECK(system.stats().watchdog_tripped);
	ImpactEvent event;
	event.direction = { 0.0, 1.0, 0.0 };
	event.speed_m_per_s = 2.0; // Default material: 0.5 N s/m, 150 Hz, 30 ms.
	REQUIRE(system.push_impact(event));
	REQUIRE(system.step(DT));
	const double expected = 1.0 * std::exp(-0.001 / 0.03) * std::sin(2.0 * 3.141592653589793 * 150.0 * 0.001);
	CHECK(system.forces().total.y == doctest::Approx(expected));
}
