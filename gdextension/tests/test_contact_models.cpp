// The two contact models side by side (force_model.h): the per-contact, unilateral model
// (the default) and the paper's normalised sum. Vectors by hand in device axes (y up); a
// floor's normal is (0, 1, 0), a wall on the player's right has (-1, 0, 0).

#include "renderers/movement/force_model.h"
#include "renderers/movement/movement_renderer.h"
#include "renderers/movement/unilateral_contacts.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <iterator>
#include <limits>
#include <numbers>

using namespace haptics;

namespace {

constexpr double EPS = 1e-12;
const Vec3 FLOOR{ 0.0, 1.0, 0.0 };
const Vec3 RIGHT_WALL{ -1.0, 0.0, 0.0 };
const Vec3 LEFT_WALL{ 1.0, 0.0, 0.0 };
constexpr ContactModel PER = ContactModel::PER_CONTACT;
constexpr ContactModel PAPER = ContactModel::PAPER_SUM;

void check_vec(const Vec3 &p_actual, const Vec3 &p_expected, double p_tolerance = EPS) {
	CHECK(std::abs(p_actual.x - p_expected.x) <= p_tolerance);
	CHECK(std::abs(p_actual.y - p_expected.y) <= p_tolerance);
	CHECK(std::abs(p_actual.z - p_expected.z) <= p_tolerance);
}

ForceModelConfig model(ContactModel p_model, double p_engage = 0.05, double p_band = 0.04) {
	ForceModelConfig config;
	config.contact_model = p_model;
	config.friction_engage = p_engage;
	config.friction_band = p_band;
	config.default_contact = ContactMaterial{ 2.0, 1.0 };
	return config;
}

MovementForces forces(const Frame &p_frame, const Vec3 &p_input, ContactModel p_model, double p_engage = 0.05,
		double p_band = 0.04) {
	return compute_forces(p_frame, p_input, model(p_model, p_engage, p_band));
}

Frame frame_of(std::initializer_list<Contact> p_contacts) {
	Frame frame;
	for (const Contact &contact : p_contacts) {
		frame.contacts.push_back(contact);
	}
	return frame;
}

Contact contact(const Vec3 &p_normal, double p_k = 2.0, double p_b = 1.0) {
	return Contact{ p_normal, ContactMaterial{ p_k, p_b } };
}

Vec3 unit(double p_x, double p_y, double p_z = 0.0) {
	return normalized_or_zero(Vec3{ p_x, p_y, p_z });
}

} // namespace

TEST_CASE("contact models: one pressed contact gives the paper's forces in both") {
	for (const double degrees : { 0.0, 20.0, 90.0, 135.0, 200.0, 300.0 }) {
		const double angle = degrees * std::numbers::pi / 180.0;
		const Vec3 n{ std::cos(angle), std::sin(angle), 0.0 };
		const Vec3 t{ -n.y, n.x, 0.0 };
		// Pressing deeper than friction_band + friction_engage: normal force and friction identical.
		for (const Vec3 &i : { n * -0.6 + t * 0.3, n * -0.1 - t * 0.7, n * -0.3 + Vec3{ 0.0, 0.0, 0.4 } }) {
			CAPTURE(degrees);
			const Frame frame = frame_of({ contact(n * 3.0, 2.5, 1.5) }); // Any length.
			const MovementForces per = forces(frame, i, PER);
			const MovementForces paper = forces(frame, i, PAPER);
			check_vec(per.normal, paper.normal, 1e-12);
			check_vec(per.friction, paper.friction, 1e-12);
		}
		// Pressing less: the normal force is still the paper's; friction fades in past the band.
		const Frame frame = frame_of({ contact(n) });
		const Vec3 light = n * -0.05 + t * 0.5;
		check_vec(forces(frame, light, PER).normal, forces(frame, light, PAPER).normal, 1e-12);
		check_vec(forces(frame, light, PER).friction, forces(frame, light, PAPER).friction * 0.2, 1e-12);
	}
}

TEST_CASE("contact models: pulling away from a wall still in contact") {
	// The measurement: |i| = 0.47 away from a wall, k = 2.
	const Frame frame = frame_of({ contact(RIGHT_WALL) });
	const Vec3 away{ -0.47, 0.0, 0.0 };
	SUBCASE("paper_sum pulls the hand into the wall with k |i|") {
		check_vec(forces(frame, away, PAPER).normal, { 0.94, 0.0, 0.0 });
	}
	SUBCASE("per_contact renders nothing, also for a diagonal pull (no friction either)") {
		check_vec(forces(frame, away, PER).continuous, {});
		check_vec(forces(frame, { -0.3, 0.4, 0.1 }, PER).continuous, {});
		check_vec(forces(frame, { -0.3, 0.4, 0.1 }, PAPER).friction, { 0.0, -0.4, -0.1 });
	}
	SUBCASE("away from a floor and a wall at once: nothing") {
		const Frame corner = frame_of({ contact(FLOOR), contact(RIGHT_WALL) });
		check_vec(forces(corner, { -0.5, 0.5, 0.0 }, PER).continuous, {});
		check_vec(forces(corner, { -0.5, 0.5, 0.0 }, PAPER).normal, { 1.0, -1.0, 0.0 });
	}
}

TEST_CASE("contact models: floor and wall, a horizontal push into the wall") {
	const Frame frame = frame_of({ contact(FLOOR, 2.0, 1.0), contact(RIGHT_WALL, 2.0, 1.0) });
	const Vec3 push{ 0.6, 0.0, 0.0 };
	SUBCASE("per_contact: exactly the wall's push-back, nothing upward, no friction") {
		const MovementForces f = forces(frame, push, PER);
		check_vec(f.normal, { -1.2, 0.0, 0.0 });
		check_vec(f.friction, {});
		const Frame wall_alone = frame_of({ contact(RIGHT_WALL, 2.0, 1.0) });
		check_vec(f.continuous, forces(wall_alone, push, PER).continuous);
	}
	SUBCASE("paper_sum: the 45 degree normal pushes up by k |i| / 2") {
		const MovementForces f = forces(frame, push, PAPER);
		check_vec(f.normal, { -0.6, 0.6, 0.0 });
		check_vec(f.friction, { -0.3, -0.3, 0.0 });
	}
	SUBCASE("per_contact: the wall's own material, whatever the floor's") {
		const Frame mixed = frame_of({ contact(FLOOR, 9.0, 9.0), contact(RIGHT_WALL, 4.0, 1.0) });
		check_vec(forces(mixed, push, PER).normal, { -2.4, 0.0, 0.0 });
	}
}

TEST_CASE("contact models: a 90 degree corner, pushing into both") {
	// Floor k = 2, wall on the left k = 4; i presses 0.4 into the floor and 0.3 into the wall.
	const Frame frame = frame_of({ contact(FLOOR, 2.0, 1.0), contact(LEFT_WALL, 4.0, 3.0) });
	const Vec3 i{ -0.3, -0.4, 0.0 };
	const MovementForces f = forces(frame, i, PER);
	check_vec(f.normal, { 1.2, 0.8, 0.0 }); // Each its own component with its own k.
	check_vec(f.friction, {}); // Nothing slides in a corner.
	// Sliding in depth rubs on both surfaces (both pushes exceed friction_engage).
	check_vec(forces(frame, { -0.3, -0.4, 0.2 }, PER).friction, { 0.0, 0.0, -0.8 });
	// Equal materials and an input along the bisector: the paper's answer, -k i.
	const Frame equal = frame_of({ contact(FLOOR), contact(LEFT_WALL) });
	const Vec3 diagonal{ -0.5, -0.5, 0.0 };
	check_vec(forces(equal, diagonal, PER).normal, { 1.0, 1.0, 0.0 });
	check_vec(forces(equal, diagonal, PAPER).normal, { 1.0, 1.0, 0.0 });
}

TEST_CASE("contact models: an obtuse corner, a floor meeting a 45 degree ramp") {
	// The ramp rises to the right: its normal points up and left.
	const Vec3 ramp = unit(-1.0, 1.0);
	const Frame frame = frame_of({ contact(FLOOR), contact(ramp) });
	SUBCASE("straight down: the floor blocks it once, the ramp adds nothing") {
		check_vec(forces(frame, { 0.0, -0.8, 0.0 }, PER).normal, { 0.0, 1.6, 0.0 });
		// Summing the pressing depths k d_j n_j would have pushed (-0.8, 2.4): 1.6 times
		// as hard, and sideways.
	}
	SUBCASE("horizontally into the ramp: slides up it, pushed back along the ramp's normal") {
		// lambda = 0.5 / sqrt 2, free part (0.25, 0.25) along the ramp.
		const MovementForces f = forces(frame, { 0.5, 0.0, 0.0 }, PER);
		check_vec(f.normal, { -0.5, 0.5, 0.0 });
		check_vec(f.friction, { -0.25, -0.25, 0.0 });
	}
	SUBCASE("down and right, between both normals: blocked entirely, -k i") {
		const MovementForces f = forces(frame, { 0.2, -0.6, 0.0 }, PER);
		check_vec(f.normal, { -0.4, 1.2, 0.0 });
		check_vec(f.friction, {});
	}
}

TEST_CASE("contact models: an acute wedge holds an input one contact does not face") {
	// Floor and an overhang above it closing in on the left (normal down and right).
	const Vec3 overhang{ 0.6, -0.8, 0.0 };
	const Frame frame = frame_of({ contact(FLOOR), contact(overhang) });
	const Vec3 i{ -0.5, -0.5, 0.0 }; // i.overhang = +0.1: not pressed directly...
	UnilateralContacts contacts;
	resolve_unilateral(frame, i, ContactMaterial{}, contacts);
	CHECK(contacts.pushes[0] == doctest::Approx(7.0 / 6.0));
	CHECK(contacts.pushes[1] == doctest::Approx(5.0 / 6.0)); // ...but it holds the slide.
	check_vec(contacts.free, {}, 1e-12);
	check_vec(forces(frame, i, PER).normal, { 1.0, 1.0, 0.0 }, 1e-12);
}

TEST_CASE("contact models: opposed contacts, squeezed between two walls") {
	const Frame frame = frame_of({ contact(LEFT_WALL, 2.0, 1.0), contact(RIGHT_WALL, 4.0, 2.0) });
	SUBCASE("per_contact: the wall pressed pushes back with its own material") {
		const MovementForces right = forces(frame, { 0.4, 0.3, 0.0 }, PER);
		check_vec(right.normal, { -1.6, 0.0, 0.0 });
		check_vec(right.friction, { 0.0, -0.6, 0.0 });
		check_vec(forces(frame, { -0.4, 0.3, 0.0 }, PER).normal, { 0.8, 0.0, 0.0 });
		check_vec(forces(frame, { 0.0, 0.3, 0.0 }, PER).continuous, {}); // Along both.
	}
	SUBCASE("paper_sum: the normals cancel and nothing is rendered") {
		check_vec(forces(frame, { 0.4, 0.3, 0.0 }, PAPER).continuous, {});
	}
}

TEST_CASE("contact models: one surface reported twice pushes once, with the averaged material") {
	const Vec3 i{ 0.3, -0.5, 0.0 };
	const Frame one = frame_of({ contact(FLOOR, 3.0, 2.0) });
	for (const Vec3 &second : { FLOOR, FLOOR * 5.0, unit(1e-4, 1.0) }) {
		const Frame twice = frame_of({ contact(FLOOR, 2.0, 1.0), contact(second, 4.0, 3.0) });
		const MovementForces f = forces(twice, i, PER);
		check_vec(f.normal, forces(one, i, PER).normal, 1e-4);
		check_vec(f.friction, forces(one, i, PER).friction, 1e-4);
	}
	// Two surfaces 2 degrees apart are not merged, and still do not double the push.
	const Frame kinked = frame_of({ contact(unit(-0.0175, 1.0)), contact(unit(0.0175, 1.0)) });
	const MovementForces f = forces(kinked, { 0.0, -0.5, 0.0 }, PER);
	CHECK(length(f.normal) == doctest::Approx(1.0).epsilon(1e-3));
}

TEST_CASE("contact models: sliding and friction") {
	const Frame floor = frame_of({ contact(FLOOR, 2.0, 1.0) });
	SUBCASE("along a floor without pressing it: free with per_contact, -b r with paper_sum") {
		check_vec(forces(floor, { 0.5, 0.0, 0.0 }, PER).friction, {});
		check_vec(forces(floor, { 0.5, 0.0, 0.0 }, PAPER).friction, { -0.5, 0.0, 0.0 });
	}
	SUBCASE("friction fades in over friction_engage past friction_band, then is the paper's") {
		check_vec(forces(floor, { 0.5, -0.065, 0.0 }, PER).friction, { -0.25, 0.0, 0.0 });
		check_vec(forces(floor, { 0.5, -0.1, 0.0 }, PER).friction, { -0.5, 0.0, 0.0 });
		// No band and friction_engage 0: the paper's -b r at any pressing.
		check_vec(forces(floor, { 0.5, -1e-9, 0.0 }, PER, 0.0, 0.0).friction, { -0.5, 0.0, 0.0 });
	}
	SUBCASE("a hand trembling a few per cent about a floor's plane never switches friction") {
		// The hand 0.42 along the floor, drifting +-3 % across its plane: the friction
		// stays within 0.1 N (it does not change at all), and the normal force is k p.
		const Frame hard = frame_of({ contact(FLOOR, 2.0, 2.5) });
		double lowest = 1e9;
		double highest = -1e9;
		for (int s = -30; s <= 30; ++s) {
			const MovementForces f = forces(hard, { 0.42, s * 0.001, 0.0 }, PER);
			lowest = std::min(lowest, length(f.friction));
			highest = std::max(highest, length(f.friction));
			CHECK(f.normal.y == doctest::Approx(2.0 * std::max(0.0, -s * 0.001)).epsilon(1e-9));
		}
		CHECK(highest - lowest < 0.1);
		// Without the band the same drift took friction from 0 to 0.63 N.
		const MovementForces banned = forces(hard, { 0.42, -0.03, 0.0 }, PER, 0.05, 0.0);
		CHECK(length(banned.friction) == doctest::Approx(0.63));
		// Clearly pressed (band plus engage and beyond): the paper's -b r exactly.
		check_vec(forces(hard, { 0.42, -0.2, 0.0 }, PER).friction, { -1.05, 0.0, 0.0 });
	}
	SUBCASE("standing on a floor by a wall") {
		const Frame frame = frame_of({ contact(FLOOR, 2.0, 1.0), contact(LEFT_WALL, 2.0, 3.0) });
		// Into the wall and up, off the floor: the wall's friction against the slide up.
		check_vec(forces(frame, { -0.4, 0.5, 0.0 }, PER).friction, { 0.0, -1.5, 0.0 });
		// Into the wall and down into the floor: stuck in the corner, nothing slides.
		check_vec(forces(frame, { -0.4, -0.5, 0.0 }, PER).friction, {});
		// Walking away from the wall while pressing the floor: the floor alone, as the paper.
		check_vec(forces(frame, { 0.5, -0.4, 0.0 }, PER).friction, { -0.5, 0.0, 0.0 });
		check_vec(forces(frame, { 0.5, -0.4, 0.0 }, PER).normal, { 0.0, 0.8, 0.0 });
	}
}

TEST_CASE("contact models: per_contact is continuous in the input, around every kind of corner") {
	// Sweeping the input's direction finely: no step larger than a Lipschitz bound. The
	// friction ramp (b / friction_engage) is the steepest part.
	const Vec3 ramp = unit(-1.0, 1.0);
	const Vec3 overhang{ 0.6, -0.8, 0.0 };
	const Frame frames[] = {
		frame_of({ contact(FLOOR, 2.0, 1.0) }),
		frame_of({ contact(FLOOR, 2.0, 1.0), contact(RIGHT_WALL, 3.0, 1.5) }),
		frame_of({ contact(FLOOR, 3.0, 1.0), contact(ramp, 2.0, 1.5) }),
		frame_of({ contact(FLOOR, 2.0, 1.5), contact(overhang, 3.0, 1.0) }),
		frame_of({ contact(LEFT_WALL, 2.0, 1.0), contact(RIGHT_WALL, 3.0, 1.5) }),
		frame_of({ contact(FLOOR), contact(LEFT_WALL), contact(ramp), contact(overhang) }),
	};
	constexpr int STEPS = 7200;
	const double step_length = 0.8 * 2.0 * std::numbers::pi / STEPS;
	for (size_t c = 0; c < std::size(frames); ++c) {
		CAPTURE(c);
		Vec3 previous = forces(frames[c], { 0.8, 0.0, 0.1 }, PER).continuous;
		double largest = 0.0;
		for (int s = 1; s <= STEPS; ++s) {
			const double angle = 2.0 * std::numbers::pi * s / STEPS;
			const Vec3 now = forces(frames[c], { 0.8 * std::cos(angle), 0.8 * std::sin(angle), 0.1 }, PER).continuous;
			largest = std::max(largest, length(now - previous));
			previous = now;
		}
		CHECK(largest <= 60.0 * step_length); // 0.04 N; the friction gate alone jumps ~0.8 N.
	}
}

TEST_CASE("contact models: a contact that appears unpressed changes nothing") {
	const Frame floor = frame_of({ contact(FLOOR) });
	const Frame with_wall = frame_of({ contact(FLOOR), contact(RIGHT_WALL, 9.0, 9.0) });
	const Vec3 i{ -0.4, -0.3, 0.1 }; // Away from the wall on the right.
	check_vec(forces(with_wall, i, PER).continuous, forces(floor, i, PER).continuous);
	// Barely pressed, it barely adds: the push starts from zero.
	const Vec3 barely{ 1e-6, -0.3, 0.1 };
	CHECK(length(forces(with_wall, barely, PER).continuous - forces(floor, barely, PER).continuous) < 1e-4);
	// The paper's combined normal turns by 45 degrees at once.
	CHECK(length(forces(with_wall, i, PAPER).normal - forces(floor, i, PAPER).normal) > 0.3);
}

TEST_CASE("contact models: degenerate normals are skipped, a non-finite input renders nothing") {
	const double nan = std::numeric_limits<double>::quiet_NaN();
	const double inf = std::numeric_limits<double>::infinity();
	const Vec3 i{ 0.3, -0.5, 0.0 };
	const Frame floor = frame_of({ contact(FLOOR) });
	const Frame junk = frame_of({ contact({ nan, 0.0, 0.0 }), contact(FLOOR), contact({}), contact({ inf, 1.0, 0.0 }) });
	check_vec(forces(junk, i, PER).continuous, forces(floor, i, PER).continuous);
	const MovementForces f = forces(floor, { nan, 0.0, 0.0 }, PER);
	check_vec(f.normal, {});
	check_vec(f.friction, {});
}

TEST_CASE("contact models: the solver's answer is the projection (KKT), for random contacts") {
	// Optimality of min |i + sum lambda_j n_j|^2, lambda >= 0, is exactly: lambda_j >= 0, the
	// free part a presses into no contact (a.n_j >= 0), and only contacts it rests on
	// push (lambda_j > 0 => a.n_j = 0). Planar normals (the game) and spatial ones.
	uint64_t state = 12345;
	const auto uniform = [&state]() {
		state = state * 6364136223846793005ull + 1442695040888963407ull;
		return static_cast<double>(state >> 11) / static_cast<double>(1ull << 53) * 2.0 - 1.0;
	};
	int active_most = 0;
	for (int trial = 0; trial < 4000; ++trial) {
		const bool planar = trial % 2 == 0;
		Frame frame;
		const int count = 1 + trial % 7;
		for (int c = 0; c < count; ++c) {
			add_contact(frame, { uniform(), uniform(), planar ? 0.0 : uniform() });
		}
		const Vec3 i{ uniform(), uniform(), uniform() * 0.5 };
		UnilateralContacts contacts;
		resolve_unilateral(frame, i, ContactMaterial{}, contacts);
		Vec3 blocked;
		int active = 0;
		for (uint32_t j = 0; j < contacts.count; ++j) {
			const double lambda = contacts.pushes[j];
			const double rest = dot(contacts.free, contacts.normals[j]);
			CHECK(lambda >= 0.0);
			CHECK(rest >= -1e-9);
			if (lambda > 0.0) {
				CHECK(std::abs(rest) <= 1e-9);
				++active;
			}
			blocked -= contacts.normals[j] * lambda;
		}
		check_vec(blocked, contacts.blocked, 1e-12);
		check_vec(contacts.free + contacts.blocked, i, 1e-12);
		CHECK(active <= (planar ? 2 : 3));
		active_most = std::max(active_most, active);
	}
	CHECK(active_most == 3);
}

TEST_CASE("contact models: weight and water are the paper's in both") {
	Frame frame;
	add_contact(frame, FLOOR);
	add_resting(frame, { 0.0, -1.0, 0.0 }, 1.5);
	set_water(frame, true, 0.5, 0.25);
	frame.velocity_m_per_s = { 1.0, 0.0, 0.0 };
	for (const ContactModel m : { PER, PAPER }) {
		const MovementForces f = forces(frame, { 0.4, 0.3, 0.0 }, m);
		check_vec(f.weight, { 0.0, -1.5, 0.0 });
		check_vec(f.drag, { -0.5, 0.0, 0.0 });
		check_vec(f.inertia, { 0.0, -0.25, 0.0 });
	}
}

TEST_CASE("contact models: the movement renderer follows the configured model") {
	MovementChannels channels;
	MovementRenderer renderer(channels);
	MovementConfig config;
	config.smoothing.enabled = false;
	channels.settings.store(config);
	renderer.pick_up_settings(0.001, true);
	renderer.begin_session(0.001);
	const Frame frame = frame_of({ contact(FLOOR), contact(RIGHT_WALL) });
	const DeviceState device;
	RenderResult result;
	const Vec3 push{ 0.6, 0.0, 0.0 };
	renderer.render(RenderInput{ device, push, frame, true, 0.001, 0.1, false }, result);
	check_vec(result.continuous, { -1.2, 0.0, 0.0 }); // The default: per_contact.
	config.force_model.contact_model = PAPER;
	channels.settings.store(config);
	renderer.pick_up_settings(0.001, false);
	renderer.render(RenderInput{ device, push, frame, false, 0.001, 0.1, false }, result);
	check_vec(result.continuous, { -0.9, 0.3, 0.0 }); // -k p and -b r on the 45 degree normal.
}
