// The movement-based force model, equation by equation, with vectors computed by hand: the
// paper's literal contact model (PAPER_SUM) for eqs. 1-4, and weight and water, which both
// models share. The per-contact model and the comparisons are in test_contact_models.cpp.

#include "core/base/coordinates.h"
#include "core/servo/input_vector.h"
#include "renderers/movement/force_model.h"

#include <doctest/doctest.h>

#include <cmath>
#include <initializer_list>
#include <numbers>

using namespace haptics;

namespace {

constexpr double EPS = 1e-12;

void check_vec(const Vec3 &p_actual, const Vec3 &p_expected, double p_tolerance = EPS) {
	CHECK(std::abs(p_actual.x - p_expected.x) <= p_tolerance);
	CHECK(std::abs(p_actual.y - p_expected.y) <= p_tolerance);
	CHECK(std::abs(p_actual.z - p_expected.z) <= p_tolerance);
}

ForceModelConfig config_with(double p_k, double p_b, double p_gravity = 1.0,
		ContactModel p_model = ContactModel::PAPER_SUM) {
	ForceModelConfig config;
	config.gravity_n_per_kg = p_gravity;
	config.default_contact = ContactMaterial{ p_k, p_b };
	config.contact_model = p_model;
	return config;
}

} // namespace

TEST_CASE("coordinates: game (x right, y down) maps to device (x right, y up, z toward user)") {
	check_vec(game_to_device_direction(1.0, 2.0), Vec3{ 1.0, -2.0, 0.0 });
	check_vec(game_to_device_scaled(300.0, -150.0, 100.0), Vec3{ 3.0, 1.5, 0.0 });
	const GameVec2 back = device_to_game(Vec3{ 0.25, 0.5, 0.75 });
	CHECK(back.x == 0.25);
	CHECK(back.y == -0.5);
	// "Down" on screen is down for the device.
	check_vec(game_to_device_direction(0.0, 1.0), DEVICE_DOWN);
}

TEST_CASE("input vector: position over radius, clamped to the unit ball") {
	check_vec(input_vector({ 0.05, 0.0, 0.0 }, 0.1, 0.0), { 0.5, 0.0, 0.0 });
	// The paper's examples: furthest right -> [1, 0, 0]; furthest down -> [0, -1, 0].
	check_vec(input_vector({ 0.1, 0.0, 0.0 }, 0.1, 0.0), { 1.0, 0.0, 0.0 });
	check_vec(input_vector({ 0.0, -0.1, 0.0 }, 0.1, 0.0), { 0.0, -1.0, 0.0 });
	// Outside the workspace: clamped to length 1, direction kept (3-4-5 triangle).
	check_vec(input_vector({ 0.3, 0.4, 0.0 }, 0.1, 0.0), { 0.6, 0.8, 0.0 });
	check_vec(input_vector({}, 0.1, 0.0), {});
}

TEST_CASE("input vector: dead zone is rescaled so the output is continuous") {
	const double dz = 0.1;
	check_vec(input_vector({ 0.005, 0.0, 0.0 }, 0.1, dz), {}); // |raw| = 0.05 inside.
	check_vec(input_vector({ 0.01, 0.0, 0.0 }, 0.1, dz), {}); // Exactly on the edge.
	// |raw| = 0.5 -> (0.5 - 0.1) / 0.9 = 0.4444...
	check_vec(input_vector({ 0.0, 0.05, 0.0 }, 0.1, dz), { 0.0, 0.4 / 0.9, 0.0 });
	// Just outside the edge the output is tiny, not a jump.
	const Vec3 just_outside = input_vector({ 0.01 + 1e-9, 0.0, 0.0 }, 0.1, dz);
	CHECK(length(just_outside) < 1e-7);
	// Still reaches 1 at the workspace edge.
	CHECK(length(input_vector({ 0.0, 0.0, 0.1 }, 0.1, dz)) == doctest::Approx(1.0));
}

TEST_CASE("eqs 1-4: projection, rejection, normal force and friction on a floor") {
	Frame frame;
	add_contact(frame, { 0.0, 1.0, 0.0 }); // Floor: normal points up at the player.
	const Vec3 i{ 0.3, -0.5, 0.0 }; // Pushing down and right.
	// p = (0, -0.5, 0), r = (0.3, 0, 0); F_n = -2 p, F_f = -1 r.
	const MovementForces f = compute_forces(frame, i, config_with(2.0, 1.0));
	check_vec(f.normal, { 0.0, 1.0, 0.0 });
	check_vec(f.friction, { -0.3, 0.0, 0.0 });
	check_vec(f.continuous, { -0.3, 1.0, 0.0 });
	check_vec(f.weight, {});
	check_vec(f.drag, {});
	check_vec(f.inertia, {});
}

TEST_CASE("eqs 1-4: a sloped surface, a non-unit normal and a depth component") {
	Frame frame;
	add_contact(frame, { 1.2, 1.6, 0.0 }, ContactMaterial{ 2.0, 0.5 }); // |n| = 2, unit (0.6, 0.8).
	const Vec3 i{ 0.5, -0.5, 0.1 };
	// i.n = 0.3 - 0.4 = -0.1 -> p = (-0.06, -0.08, 0), r = (0.56, -0.42, 0.1).
	const MovementForces f = compute_forces(frame, i, config_with(9.0, 9.0));
	check_vec(f.normal, { 0.12, 0.16, 0.0 });
	check_vec(f.friction, { -0.28, 0.21, -0.05 });
	// Pulling away from the surface (i.n > 0) gives a force toward it: the paper's model is
	// symmetric, the game decides when a contact exists.
	const MovementForces away = compute_forces(frame, { 0.6, 0.8, 0.0 }, config_with(9.0, 9.0));
	check_vec(away.normal, { -1.2, -1.6, 0.0 });
	check_vec(away.friction, {});
}

TEST_CASE("no contact: no normal force and no friction") {
	const Frame frame;
	const MovementForces f = compute_forces(frame, { 0.7, -0.7, 0.0 }, config_with(2.0, 1.0));
	check_vec(f.normal, {});
	check_vec(f.friction, {});
	check_vec(f.continuous, {});
}

TEST_CASE("several contacts: normalised sum of normals, materials weighted by share") {
	Frame frame;
	add_contact(frame, { 0.0, 1.0, 0.0 }, ContactMaterial{ 2.0, 1.0 }); // Floor.
	add_contact(frame, { -1.0, 0.0, 0.0 }, ContactMaterial{ 4.0, 3.0 }); // Wall on the right.
	const ContactResolution resolved = resolve_contacts(frame, ContactMaterial{});
	REQUIRE(resolved.active);
	check_vec(resolved.normal, Vec3{ -1.0, 1.0, 0.0 } / std::sqrt(2.0));
	CHECK(resolved.stiffness == doctest::Approx(3.0)); // Equal shares.
	CHECK(resolved.friction == doctest::Approx(2.0));
	// i = (0.6, -0.2, 0): i.n = -0.8/sqrt2 -> p = (0.4, -0.4, 0), r = (0.2, 0.2, 0).
	const MovementForces f = compute_forces(frame, { 0.6, -0.2, 0.0 }, config_with(0.0, 0.0));
	check_vec(f.normal, { -1.2, 1.2, 0.0 });
	check_vec(f.friction, { -0.4, -0.4, 0.0 });
}

TEST_CASE("several contacts: a contact facing away from the combined normal has no share") {
	Frame frame;
	add_contact(frame, { 0.0, 1.0, 0.0 }, ContactMaterial{ 50.0, 50.0 }); // Floor.
	add_contact(frame, { 0.0, -1.0, 0.0 }, ContactMaterial{ 50.0, 50.0 }); // Ceiling.
	add_contact(frame, { 1.0, 0.0, 0.0 }, ContactMaterial{ 2.0, 1.0 }); // Wall on the left.
	const ContactResolution resolved = resolve_contacts(frame, ContactMaterial{});
	check_vec(resolved.normal, { 1.0, 0.0, 0.0 });
	CHECK(resolved.stiffness == doctest::Approx(2.0));
	CHECK(resolved.friction == doctest::Approx(1.0));
	const MovementForces f = compute_forces(frame, { -0.5, 0.25, 0.0 }, config_with(0.0, 0.0));
	check_vec(f.normal, { 1.0, 0.0, 0.0 });
	check_vec(f.friction, { 0.0, -0.25, 0.0 });
}

TEST_CASE("several contacts: opposite normals cancel and render nothing") {
	Frame frame;
	add_contact(frame, { 1.0, 0.0, 0.0 });
	add_contact(frame, { -1.0, 0.0, 0.0 });
	CHECK_FALSE(resolve_contacts(frame, ContactMaterial{}).active);
	const MovementForces f = compute_forces(frame, { 0.5, 0.5, 0.0 }, config_with(2.0, 1.0));
	check_vec(f.continuous, {});
}

TEST_CASE("default material applies to contacts that ask for it") {
	Frame frame;
	add_contact(frame, { 0.0, 1.0, 0.0 }); // No material: the default
	const MovementForces f = compute_forces(frame, { 0.0, -0.5, 0.0 }, config_with(3.0, 1.0));
	check_vec(f.normal, { 0.0, 1.5, 0.0 });
}

TEST_CASE("eq 5: weight only when n.d > 0") {
	const ForceModelConfig config = config_with(0.0, 0.0, 1.5);
	SUBCASE("a crate lying on the player is felt: W = m g (n.d) d") {
		Frame frame;
		// The crate is above; its contact normal points down, at the player. Given in game
		// space (y down) to exercise the one mapping.
		add_resting(frame, game_to_device_direction(0.0, 1.0), 2.0);
		check_vec(compute_forces(frame, {}, config).weight, { 0.0, -3.0, 0.0 });
	}
	SUBCASE("standing on a crate is not felt") {
		Frame frame;
		add_resting(frame, game_to_device_direction(0.0, -1.0), 2.0);
		check_vec(compute_forces(frame, {}, config).weight, {});
	}
	SUBCASE("touching a crate's side is not felt") {
		Frame frame;
		add_resting(frame, { 1.0, 0.0, 0.0 }, 2.0);
		add_resting(frame, { -1.0, 0.0, 0.0 }, 2.0);
		check_vec(compute_forces(frame, {}, config).weight, {});
	}
	SUBCASE("a crate on a 30 degree slope of the player's head: cos 30 of its weight") {
		Frame frame;
		add_resting(frame, { 0.5, -std::sqrt(3.0) / 2.0, 0.0 }, 2.0);
		check_vec(compute_forces(frame, {}, config).weight, { 0.0, -3.0 * std::sqrt(3.0) / 2.0, 0.0 });
	}
	SUBCASE("two crates add up; a non-unit normal counts as its direction") {
		Frame frame;
		add_resting(frame, { 0.0, -4.0, 0.0 }, 1.0);
		add_resting(frame, { 0.0, -1.0, 0.0 }, 0.5);
		add_resting(frame, { 0.0, 1.0, 0.0 }, 100.0); // Stood on: ignored.
		check_vec(compute_forces(frame, {}, config).weight, { 0.0, -2.25, 0.0 });
	}
}

TEST_CASE("eqs 6-7: water drag and inertia only inside water") {
	Frame frame;
	frame.water_drag_n_s_per_m = 0.5;
	frame.water_inertia_n = 0.8;
	frame.velocity_m_per_s = { 2.0, -1.0, 0.0 };
	const ForceModelConfig config = config_with(2.0, 1.0);
	SUBCASE("outside") {
		frame.in_water = false;
		const MovementForces f = compute_forces(frame, { 0.5, 0.0, 0.0 }, config);
		check_vec(f.drag, {});
		check_vec(f.inertia, {});
		check_vec(f.continuous, {});
	}
	SUBCASE("inside") {
		frame.in_water = true;
		const MovementForces f = compute_forces(frame, { 0.5, 0.0, 0.0 }, config);
		check_vec(f.drag, { -1.0, 0.5, 0.0 }); // -c v
		check_vec(f.inertia, { 0.0, -0.8, 0.0 }); // w d
		check_vec(f.continuous, { -1.0, -0.3, 0.0 });
	}
}

TEST_CASE("the continuous sum is the sum of every component") {
	Frame frame;
	add_contact(frame, { 0.0, 1.0, 0.0 });
	add_resting(frame, { 0.0, -1.0, 0.0 }, 1.0);
	set_water(frame, true, 0.5, 0.25);
	frame.velocity_m_per_s = { 1.0, 0.0, 0.0 };
	const MovementForces f = compute_forces(frame, { 0.4, -0.6, 0.0 }, config_with(2.0, 1.0, 1.0));
	check_vec(f.normal, { 0.0, 1.2, 0.0 });
	check_vec(f.friction, { -0.4, 0.0, 0.0 });
	check_vec(f.weight, { 0.0, -1.0, 0.0 });
	check_vec(f.drag, { -0.5, 0.0, 0.0 });
	check_vec(f.inertia, { 0.0, -0.25, 0.0 });
	check_vec(f.continuous, { -0.9, -0.05, 0.0 });
}

TEST_CASE("orientation invariance: a wall at any angle gives the same forces along its own normal") {
	const double radius = 0.1;
	const double k = 2.5;
	const double b = 1.5;
	// One pressed contact: the per-contact model is the paper's (test_contact_models.cpp).
	for (const ContactModel model : { ContactModel::PAPER_SUM, ContactModel::PER_CONTACT }) {
		for (const double degrees : { 0.0, 30.0, 45.0, 90.0, 135.0, 180.0 }) {
			CAPTURE(static_cast<int>(model));
			CAPTURE(degrees);
			const double angle = degrees * std::numbers::pi / 180.0;
			// The wall's normal, given in game space like the probe would.
			const Vec3 n = game_to_device_direction(std::cos(angle), std::sin(angle));
			const Vec3 t{ -n.y, n.x, 0.0 }; // Along the wall, in the screen plane.
			const Vec3 z{ 0.0, 0.0, 1.0 };
			// Push 0.6 into the wall, slide 0.3 along it and 0.2 in depth: the same motion
			// relative to the wall at every angle, produced through the device position.
			const Vec3 position = (n * -0.6 + t * 0.3 + z * 0.2) * radius;
			const Vec3 i = input_vector(position, radius, 0.0);
			Frame frame;
			add_contact(frame, n, ContactMaterial{ k, b });
			const MovementForces f = compute_forces(frame, i, config_with(0.0, 0.0, 1.0, model));
			check_vec(f.normal, n * (0.6 * k), 1e-12);
			check_vec(f.friction, t * (-0.3 * b) + z * (-0.2 * b), 1e-12);
			CHECK(dot(f.normal, n) == doctest::Approx(1.5));
			CHECK(length(f.normal) == doctest::Approx(1.5));
			CHECK(length(f.friction) == doctest::Approx(std::sqrt(0.13) * b));
			CHECK(std::abs(dot(f.normal, f.friction)) < 1e-12);
		}
	}
}
