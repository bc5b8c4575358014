// The movement-based model in three dimensions (docs/probe-3d.md derives each expectation):
// a 3D game's contacts, resting objects and water, in device axes (x right, y up, z toward
// the user), under both contact models.

#include "core/base/coordinates.h"
#include "renderers/movement/force_model.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

using namespace haptics;

namespace {

constexpr double TOLERANCE = 1e-9;
const double HALF_ROOT_2 = std::sqrt(0.5);

void check_vec(const Vec3 &p_actual, const Vec3 &p_expected, double p_tolerance = TOLERANCE) {
	INFO("actual (", p_actual.x, ", ", p_actual.y, ", ", p_actual.z, ") expected (", p_expected.x, ", ",
			p_expected.y, ", ", p_expected.z, ")");
	CHECK(length(p_actual - p_expected) <= p_tolerance);
}

ForceModelConfig model(ContactModel p_model, double p_k = 2.0, double p_b = 1.0) {
	ForceModelConfig config;
	config.contact_model = p_model;
	config.default_contact = ContactMaterial{ p_k, p_b };
	return config;
}

// Past the friction band and its fade: the paper's -b r in full (force_model.h).
double full_rub(const ForceModelConfig &p_config, double p_push) {
	return std::clamp((p_push - p_config.friction_band) / p_config.friction_engage, 0.0, 1.0);
}

} // namespace

TEST_CASE("3D model: pressing a floor while moving forward and right: F_n up, friction against the slide") {
	// i = (0.3, -0.5, -0.4) on a floor n = (0, 1, 0): p = (0, -0.5, 0), r = (0.3, 0, -0.4).
	Frame frame;
	add_contact(frame, { 0.0, 1.0, 0.0 });
	const Vec3 input{ 0.3, -0.5, -0.4 };
	for (const ContactModel contact_model : { ContactModel::PAPER_SUM, ContactModel::PER_CONTACT }) {
		const ForceModelConfig config = model(contact_model);
		const MovementForces f = compute_forces(frame, input, config);
		check_vec(f.normal, { 0.0, 1.0, 0.0 });
		const double rub = contact_model == ContactModel::PAPER_SUM ? 1.0 : full_rub(config, 0.5);
		CHECK(rub == doctest::Approx(1.0));
		check_vec(f.friction, Vec3{ -0.3, 0.0, 0.4 } * rub);
	}
}

TEST_CASE("3D model: a corner of floor and two walls pushes back each face's own part of the input") {
	// Floor (0, 1, 0), a wall on the left (1, 0, 0), one in front (0, 0, 1); the input presses
	// into all three: lambda_j = -i.n_j each, F_n = k (0.3, 0.4, 0.5), nothing left to slide.
	Frame frame;
	add_contact(frame, { 0.0, 1.0, 0.0 });
	add_contact(frame, { 1.0, 0.0, 0.0 });
	add_contact(frame, { 0.0, 0.0, 1.0 });
	const Vec3 input{ -0.3, -0.4, -0.5 };
	const MovementForces f = compute_forces(frame, input, model(ContactModel::PER_CONTACT));
	check_vec(f.normal, { 0.6, 0.8, 1.0 });
	check_vec(f.friction, {});
	// The paper's sum: n = (1, 1, 1)/sqrt 3, p = (i.n) n = -0.4 (1, 1, 1), F_n = -k p.
	const MovementForces paper = compute_forces(frame, input, model(ContactModel::PAPER_SUM, 2.0, 0.0));
	check_vec(paper.normal, { 0.8, 0.8, 0.8 });
}

TEST_CASE("3D model: a ramp rising away from the viewer answers a push down along its own normal") {
	// n = (0, 1, 1)/sqrt 2 (the slope climbs toward -z); i = (0, -0.6, 0): lambda = -i.n =
	// 0.6/sqrt 2, F_n = k lambda n = (0, 0.6, 0.6); the free part a = i + lambda n =
	// (0, -0.3, 0.3) slides down the slope, toward the viewer.
	Frame frame;
	add_contact(frame, { 0.0, HALF_ROOT_2, HALF_ROOT_2 });
	const Vec3 input{ 0.0, -0.6, 0.0 };
	const ForceModelConfig config = model(ContactModel::PER_CONTACT);
	const MovementForces f = compute_forces(frame, input, config);
	check_vec(f.normal, { 0.0, 0.6, 0.6 });
	const double push = 0.6 * HALF_ROOT_2;
	check_vec(f.friction, Vec3{ 0.0, -0.3, 0.3 } * (-1.0 * full_rub(config, push)));
}

TEST_CASE("3D model: walking away from a wall, or along it, is not held back") {
	Frame frame;
	add_contact(frame, { 0.0, 0.0, 1.0 }); // A wall in front.
	for (const Vec3 input : { Vec3{ 0.0, 0.0, 0.7 }, Vec3{ 0.5, 0.0, 0.0 }, Vec3{ -0.2, 0.3, 0.4 } }) {
		const MovementForces f = compute_forces(frame, input, model(ContactModel::PER_CONTACT));
		check_vec(f.continuous, {});
	}
}

TEST_CASE("3D model: weight only from objects pressing down, by n.d, whatever their sideways lean") {
	// W = m g (n.d) d for n.d > 0 (eq. 5): a crate on the head leaning forward and right,
	// n = (0.48, -0.8, 0.36): n.d = 0.8; one the player stands on (n.d < 0) weighs nothing.
	Frame frame;
	add_resting(frame, { 0.48, -0.8, 0.36 }, 2.0);
	add_resting(frame, { 0.0, 1.0, 0.0 }, 5.0);
	ForceModelConfig config = model(ContactModel::PER_CONTACT);
	config.gravity_n_per_kg = 1.5;
	const MovementForces f = compute_forces(frame, {}, config);
	check_vec(f.weight, { 0.0, -2.0 * 1.5 * 0.8, 0.0 });
}

TEST_CASE("3D model: water drags against the 3D velocity and pulls along down") {
	Frame frame;
	set_water(frame, true, 0.8, 0.4);
	frame.velocity_m_per_s = { 1.0, -0.5, 2.0 };
	const MovementForces f = compute_forces(frame, {}, model(ContactModel::PER_CONTACT));
	check_vec(f.drag, { -0.8, 0.4, -1.6 });
	check_vec(f.inertia, { 0.0, -0.4, 0.0 });
	check_vec(f.continuous, { -0.8, 0.0, -1.6 });
}

TEST_CASE("3D model: every force stays finite for contacts in every direction") {
	// A sphere of normals and inputs: nothing non-finite, and the normal force never exceeds
	// k |i| times the number of contacts pressing.
	for (int a = 0; a < 12; ++a) {
		for (int b = 0; b < 6; ++b) {
			const double theta = a * 0.5236;
			const double phi = -1.3 + b * 0.5;
			const Vec3 normal{ std::cos(phi) * std::cos(theta), std::sin(phi), std::cos(phi) * std::sin(theta) };
			Frame frame;
			add_contact(frame, normal);
			add_contact(frame, { 0.0, 1.0, 0.0 });
			const Vec3 input = normal * -0.7 + Vec3{ 0.1, -0.2, 0.05 };
			const MovementForces f = compute_forces(frame, input, model(ContactModel::PER_CONTACT));
			CHECK(std::isfinite(f.continuous.x + f.continuous.y + f.continuous.z));
			CHECK(length(f.normal) <= 2.0 * 2.0 * length(input) + TOLERANCE);
		}
	}
}
