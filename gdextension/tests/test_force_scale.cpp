// The force scale lives in the servo: one gain on every renderer's output and on impacts,
// whatever material (or none) the game gave a contact.

#include "renderers/constraint/constraint_port.h"
#include "renderers/movement/force_model.h"
#include "system/haptics_system.h"
#include "system_config.h"

#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

using namespace haptics;

namespace {

constexpr double DT = 0.001;

// Rigid hand at i = (0.3, -0.5, 0), no ramp, no slew limit, no smoothing.
void set_up(HapticsSystem &r_system, double p_scale) {
	SimulatedDeviceConfig device;
	device.rigid_hand = true;
	REQUIRE(r_system.open_simulated_device(device));
	REQUIRE(r_system.set_hand_target({ 0.03, -0.05, 0.0 }));
	REQUIRE(reconfigure(r_system, [&](RenderConfig &c) {
		c.servo.input.dead_zone = 0.0;
		c.movement.force_model.default_contact = ContactMaterial{ 2.0, 1.0 };
		c.movement.smoothing.enabled = false;
		c.servo.safety.startup_ramp_s = 0.0;
		c.servo.safety.slew_rate_n_per_s = 0.0;
		c.servo.safety.force_scale = p_scale;
	}));
}

} // namespace

TEST_CASE("force scale: scales a default-material contact, its components and the total") {
	for (const double scale : { 0.0, 0.5, 1.0, 1.5 }) {
		CAPTURE(scale);
		HapticsSystem system;
		set_up(system, scale);
		Frame frame;
		add_contact(frame, { 0.0, 1.0, 0.0 }); // No material: the default one (k = 2, b = 1).
		add_resting(frame, { 0.0, -1.0, 0.0 }, 0.5);
		REQUIRE(system.submit_frame(frame));
		REQUIRE(system.step(DT));
		const ForceComponents f = system.forces();
		CHECK(f.parts[NORMAL_FORCE].y == doctest::Approx(scale * 1.0)); // -k p, p = (0, -0.5).
		CHECK(f.parts[FRICTION_FORCE].x == doctest::Approx(scale * -0.3)); // -b r, r = (0.3, 0).
		CHECK(f.parts[WEIGHT_FORCE].y == doctest::Approx(scale * -0.5)); // m g, g = 1.
		CHECK(f.total.x == doctest::Approx(scale * -0.3));
		CHECK(f.total.y == doctest::Approx(scale * 0.5));
	}
}

TEST_CASE("force scale: scales the constraint renderer and default-material impacts") {
	HapticsSystem system;
	set_up(system, 0.5);
	const Segment2 wall{ { 50.0, -100.0 }, { 50.0, 100.0 } };
	MazeMapping mapping;
	mapping.maze_min = { -100.0, -100.0 };
	mapping.maze_max = { 100.0, 100.0 };
	mapping.workspace_half_extent_m = 0.1 * std::numbers::sqrt2; // 1 maze unit = 1 mm.
	REQUIRE(ConstraintPort(system.renderers().constraint.channels).set_geometry(&wall, 1, mapping));
	REQUIRE(system.set_hand_target({ 0.0, 0.0, 0.0 }));
	REQUIRE(reconfigure(system, [](RenderConfig &c) {
		c.servo.render_mode = RenderMode::CONSTRAINT;
		c.constraint.stiffness_n_per_m = 100.0;
		c.constraint.proxy_radius = 5.0;
	}));
	REQUIRE(system.submit_frame(Frame{}));
	REQUIRE(system.step(DT)); // The proxy is placed at the centre.
	REQUIRE(system.set_hand_target({ 0.06, 0.0, 0.0 })); // 15 mm past the wall's face at 45 mm.
	REQUIRE(system.step(DT));
	CHECK(system.forces().parts[WALL_FORCE].x == doctest::Approx(0.5 * 100.0 * -0.015).epsilon(1e-6));

	ImpactEvent event;
	event.direction = { 0.0, 1.0, 0.0 };
	event.speed_m_per_s = 2.0; // Default material: gain 0.5 N per m/s -> A = 1 N, scaled to 0.5 N.
	REQUIRE(system.push_impact(event));
	REQUIRE(system.step(DT));
	const ImpactMaterial material;
	const double expected = 0.5 * material.gain_n_s_per_m * 2.0 * std::exp(-DT / material.decay_s) *
			std::sin(2.0 * std::numbers::pi * material.frequency_hz * DT);
	CHECK(system.forces().impact.y == doctest::Approx(expected).epsilon(1e-9));
}

TEST_CASE("force scale: 0 renders nothing, out of range or NaN is refused and the old value kept") {
	HapticsSystem system;
	set_up(system, 0.0);
	Frame frame;
	add_contact(frame, { 0.0, 1.0, 0.0 });
	REQUIRE(system.submit_frame(frame));
	REQUIRE(system.step(DT));
	CHECK(system.forces().total == Vec3{});
	CHECK_FALSE(reconfigure(system, [](RenderConfig &c) { c.servo.safety.force_scale = 2.5; }));
	CHECK_FALSE(reconfigure(system, [](RenderConfig &c) { c.servo.safety.force_scale = std::nan(""); }));
	CHECK(system.config().servo.safety.force_scale == 0.0);
}
