// The ball-paddle contact law (renderers/pong/paddle_contact.h): the hand's two regimes, the paper's
// jump against the continuous default, swinging harder, the ball force's direction, the
// side memory against tunnelling, spin induction against its closed form, and the spin's grip
// that bends a spinning ball off a paddle as off a wall.

#include "pong/pong_test_support.h"

#include "renderers/pong/paddle_contact.h"
#include "renderers/pong/pong_sim.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

using namespace haptics;
using namespace haptics::test;

namespace {

constexpr Vec3 UP{ 0.0, 1.0, 0.0 };

// A horizontal paddle at the origin, the ball centre p_height above its plane.
PaddleContact touch(PaddleContactTracker &r_tracker, const PaddleLaw &p_law, double p_height,
		const Vec3 &p_ball_velocity = {}, const Vec3 &p_spin = {}) {
	PaddlePose pose;
	pose.normal = UP;
	pose.touchable = true;
	const BallState ball{ { 0.0, p_height, 0.0 }, p_ball_velocity, p_spin };
	return r_tracker.update(pose, ball, p_law, PONG_DT);
}

// The spread (max - min) of the hand force while the penetration hovers d +- p_amplitude.
double hover_spread(const PongConfig &p_config, double p_amplitude) {
	const PaddleLaw law = make_paddle_law(p_config);
	PaddleContactTracker tracker;
	double low = 1e9;
	double high = -1e9;
	for (int k = 0; k < 400; ++k) {
		const double delta = law.spring_range_m + p_amplitude * std::sin(2.0 * std::numbers::pi * k / 40.0);
		const PaddleContact contact = touch(tracker, law, law.ball_radius_m - delta);
		REQUIRE(contact.touching);
		const double force = -contact.hand_contact_n.y; // Down on the hand: the ball is above.
		low = std::min(low, force);
		high = std::max(high, force);
	}
	return high - low;
}

// Paddle 0 swings along -z at p_speed into a ball at rest (no gravity); returns the ball's
// speed as it leaves (the RELEASE event) and checks the push stays along the normal.
double swing(const Vec3 &p_paddle_velocity, Vec3 *r_ball_velocity = nullptr) {
	PongConfig config;
	config.gravity_m_per_s2 = 0.0;
	PongSim sim;
	sim.configure(config);
	const Vec3 normal{ 0.0, 0.0, -1.0 };
	const Vec3 ball{ 0.0, 1.0, 1.0 };
	sim.apply(set_ball(ball));
	PongInput input = idle_input();
	const Vec3 start = ball + Vec3{ 0.0, 0.0, config.ball_radius_m + 0.005 };
	for (int k = 0; k < 2000; ++k) {
		// The game sends the paddle every tick here, so nothing is extrapolated.
		input.players[0] = game_paddle(start + p_paddle_velocity * (k * PONG_DT), normal, p_paddle_velocity);
		sim.set_input(input);
		sim.step(PONG_DT, nullptr);
		const Vec3 force = sim.ball_contact_force();
		if (length(force) > 0.0) {
			// Perpendicular to the paddle plane, pushing the ball away from it.
			CHECK(length(cross(force, normal)) <= 1e-12 * length(force));
			CHECK(dot(force, normal) > 0.0);
		}
		for (const PongEvent &event : take_events(sim)) {
			if (event.type == PongEventType::RELEASE) {
				if (r_ball_velocity) {
					*r_ball_velocity = sim.ball().velocity;
				}
				return event.speed;
			}
		}
	}
	FAIL("the paddle never released the ball");
	return 0.0;
}

} // namespace

TEST_CASE("pong contact: the hand force below d, at d and above d") {
	PongConfig config;
	const PaddleLaw law = make_paddle_law(config);
	const double k_p = config.hand_stiffness_n_per_m;
	const double d = config.spring_range_m;
	CHECK(config.contact_force_n == doctest::Approx(k_p * d)); // Continuous by default.
	CHECK(hand_contact_force(0.5 * d, law) == doctest::Approx(k_p * 0.5 * d));
	CHECK(hand_contact_force(d, law) == doctest::Approx(k_p * d));
	CHECK(hand_contact_force(1.5 * d, law) == doctest::Approx(config.contact_force_n));
	CHECK(hand_contact_force(1.0001 * d, law) == doctest::Approx(k_p * d).epsilon(1e-3)); // No jump.

	// Through the tracker: F_h = -n_s (k_p delta), against the paddle's face toward the ball.
	PaddleContactTracker tracker;
	const double delta = 0.01;
	const PaddleContact below = touch(tracker, law, config.ball_radius_m - delta);
	REQUIRE(below.touching);
	CHECK(below.penetration_m == doctest::Approx(delta));
	CHECK(below.hand_contact_n.y == doctest::Approx(-k_p * delta));
	CHECK(below.hand_contact_n.x == 0.0);
	CHECK(below.ball_force_n.y == doctest::Approx(config.ball_stiffness_n_per_m * delta));

	// The paper's jump: c != k_p d.
	config.contact_force_n = 2.5;
	const PaddleLaw jump = make_paddle_law(config);
	CHECK(hand_contact_force(d, jump) == doctest::Approx(k_p * d));
	CHECK(hand_contact_force(1.0001 * d, jump) == doctest::Approx(2.5));
}

TEST_CASE("pong contact: around d the paper's jump chatters by |c - k_p d|, the continuous law by k_p A at most") {
	const double amplitude = 0.001; // The penetration hovers d +- 1 mm.
	PongConfig continuous;
	const double k_p = continuous.hand_stiffness_n_per_m;
	const double smooth = hover_spread(continuous, amplitude);
	PongConfig paper = continuous;
	paper.contact_force_n = 2.5; // A jump of 0.9 N at d.
	const double chatter = hover_spread(paper, amplitude);
	const double jump = std::abs(paper.contact_force_n - k_p * paper.spring_range_m);
	MESSAGE("hand force spread hovering d +- 1 mm: continuous " << smooth << " N, with the paper's jump " << chatter
																<< " N");
	CHECK(smooth <= k_p * amplitude + 1e-12);
	CHECK(chatter >= jump);
	CHECK(chatter > 20.0 * smooth);
}

TEST_CASE("pong contact: swinging harder sends a resting ball out faster, the push along the normal") {
	const double speeds[] = { 0.5, 1.0, 2.0, 3.0 };
	double previous = 0.0;
	for (const double speed : speeds) {
		const double out = swing({ 0.0, 0.0, -speed });
		MESSAGE("paddle " << speed << " m/s -> ball " << out << " m/s out");
		CHECK(out > previous);
		CHECK(out > speed); // The ball leaves faster than the paddle: it springs off it.
		CHECK(out < 2.0 * speed); // And no faster than an elastic bounce off a moving wall.
		previous = out;
	}
	// A swing with a sideways component still pushes only along the normal: the ball leaves
	// straight, the paddle's sideways motion goes into spin (in spin mode), not velocity.
	Vec3 velocity;
	swing({ 0.8, 0.0, -2.0 }, &velocity);
	CHECK(velocity.z < -2.0);
	CHECK(std::abs(velocity.x) < 1e-12);
}

TEST_CASE("pong contact: a ball crossing the plane within a tick is pushed back the way it came") {
	const PaddleLaw law = make_paddle_law(PongConfig{});
	PaddleContactTracker tracker;
	const double r = law.ball_radius_m;
	CHECK_FALSE(touch(tracker, law, r + 0.002).touching); // Above, not yet touching.
	const PaddleContact deep = touch(tracker, law, -0.3 * r); // Next tick, past the plane.
	REQUIRE(deep.touching);
	CHECK(deep.toward_ball.y == 1.0); // Still pushed up, out the side it came from.
	CHECK(deep.penetration_m == doctest::Approx(1.3 * r));
	CHECK(deep.ball_force_n.y > 0.0);
	CHECK(deep.hand_contact_n.y < 0.0);
	CHECK(tracker.side() == 1);
	// A ball that enters from below is pushed down, the other face of the two-sided disc.
	PaddleContactTracker below;
	CHECK_FALSE(touch(below, law, -r - 0.002).touching);
	const PaddleContact from_below = touch(below, law, 0.3 * r);
	REQUIRE(from_below.touching);
	CHECK(from_below.toward_ball.y == -1.0);
}

TEST_CASE("pong contact: spin under a constant paddle velocity reaches k_r ((a - p) x v_p) / k_rf") {
	PongConfig config;
	config.gravity_m_per_s2 = 0.0;
	PongSim sim;
	sim.configure(config);
	const Vec3 paddle_velocity{ 1.0, 0.0, 0.0 }; // Brushing along x under the ball.
	PongInput input = idle_input();
	input.players[0] = game_paddle({ 0.0, 1.0, 1.0 }, UP, paddle_velocity);
	input.players[0].spin = true;
	sim.set_input(input);
	const double penetration = 0.02;
	const Vec3 held{ 0.0, 1.0 + config.ball_radius_m - penetration, 1.0 };
	sim.apply(set_ball(held));
	for (int k = 0; k < 3000; ++k) {
		// Hold the ball at a fixed penetration: its position and velocity are reset every
		// tick, its spin is the simulation's own.
		sim.apply(set_ball(held, {}, sim.ball().spin));
		sim.step(PONG_DT, nullptr);
		REQUIRE(sim.contact(0).touching);
	}
	const Vec3 lever = Vec3{ 0.0, -(config.ball_radius_m - penetration), 0.0 }; // Centre -> paddle plane.
	const Vec3 expected = cross(lever, paddle_velocity) * (config.spin_gain / config.spin_friction_per_s);
	const Vec3 spin = sim.ball().spin;
	const double error = length(spin - expected) / length(expected);
	MESSAGE("steady spin " << spin.z << " rad/s, closed form " << expected.z << " rad/s, error " << error * 100.0
						   << " %");
	CHECK(error < 0.01);
	// The brush on the ball's underside drags its bottom along +x: it spins about +z, the
	// physical sense (the paper's (p - a) lever would spin it the other way).
	CHECK(spin.z > 0.0);
	// Out of spin mode the brush adds nothing and contact friction eats the spin.
	input.players[0].spin = false;
	sim.set_input(input);
	for (int k = 0; k < 1000; ++k) {
		sim.apply(set_ball(held, {}, sim.ball().spin));
		sim.step(PONG_DT, nullptr);
	}
	CHECK(length(sim.ball().spin) < length(expected) * std::exp(-config.spin_friction_per_s * 0.99));
}

TEST_CASE("pong contact: the spinning ball drags the hand along its surface, in the paddle plane") {
	PongConfig config;
	const PaddleLaw law = make_paddle_law(config);
	PaddleContactTracker tracker;
	const Vec3 spin{ 0.0, 0.0, 50.0 };
	const double penetration = 0.01;
	const PaddleContact contact = touch(tracker, law, config.ball_radius_m - penetration, {}, spin);
	REQUIRE(contact.touching);
	const Vec3 lever{ 0.0, -(config.ball_radius_m - penetration), 0.0 };
	const Vec3 expected = cross(spin, lever) * config.spin_force_gain;
	CHECK(contact.hand_spin_n.x == doctest::Approx(expected.x));
	CHECK(contact.hand_spin_n.y == doctest::Approx(0.0)); // In the paddle plane.
	// Spinning about +z, the ball's underside moves along +x: so does the paddle's drag.
	CHECK(contact.hand_spin_n.x > 0.0);
	CHECK(expected.x == doctest::Approx(50.0 * (config.ball_radius_m - penetration) * config.spin_force_gain));
}

namespace {

// A ball flying along -z at 3 m/s with p_spin onto paddle 0 at rest facing +z (no gravity);
// returns its velocity as it leaves (the RELEASE event).
Vec3 off_resting_paddle(const Vec3 &p_spin, const PongConfig &p_config) {
	PongSim sim;
	sim.configure(p_config);
	const Vec3 center{ 0.0, 1.0, 1.0 };
	PongInput input = idle_input();
	input.players[0] = game_paddle(center, { 0.0, 0.0, 1.0 });
	sim.set_input(input);
	sim.apply(set_ball(center + Vec3{ 0.0, 0.0, 0.3 }, { 0.0, 0.0, -3.0 }, p_spin));
	for (int k = 0; k < 1000; ++k) {
		sim.step(PONG_DT, nullptr);
		for (const PongEvent &event : take_events(sim)) {
			if (event.type == PongEventType::RELEASE) {
				return sim.ball().velocity;
			}
		}
	}
	FAIL("the paddle never released the ball");
	return {};
}

} // namespace

TEST_CASE("pong contact: a spinning ball bends off a resting paddle as off a wall and a plain one leaves straight") {
	PongConfig config;
	config.gravity_m_per_s2 = 0.0;
	config.air_linear_decel_m_per_s2 = 0.0; // The ball arrives with the speed and spin given.
	config.air_angular_decel_rad_per_s2 = 0.0;
	const double r = config.ball_radius_m;
	const Vec3 normal{ 0.0, 0.0, 1.0 };
	// Side spin about y: the surface facing the paddle moves along -x.
	const Vec3 side_spin{ 0.0, 30.0, 0.0 };
	const Vec3 bent = off_resting_paddle(side_spin, config);
	BallState wall{ {}, { 0.0, 0.0, -3.0 }, side_spin };
	bounce_off_plane(wall, normal, config.restitution_wall, config.surface_friction, r, 0.0);
	MESSAGE("30 rad/s side spin: sideways " << bent.x << " m/s off the paddle, " << wall.velocity.x
											<< " m/s off a wall");
	// -(2/7) (w x (-r n)): 0.6 m/s along +x, the slip stopped (friction allows 1.9 m/s).
	CHECK(bent.x == doctest::Approx(2.0 / 7.0 * side_spin.y * r).epsilon(1e-6));
	CHECK(bent.x == doctest::Approx(wall.velocity.x).epsilon(1e-6)); // The wall's law, same way.
	CHECK(std::abs(bent.y) < 1e-12);
	CHECK(bent.z > 0.0); // And it still bounces back.

	// Strong spin: Coulomb holds the sideways change to mu times the normal impulse.
	const Vec3 strong = off_resting_paddle({ 0.0, 100.0, 0.0 }, config);
	CHECK(2.0 / 7.0 * 100.0 * r > config.surface_friction * (strong.z + 3.0)); // Friction-limited.
	CHECK(strong.x == doctest::Approx(config.surface_friction * (strong.z + 3.0)).epsilon(0.01));

	// Without spin, the paper's push along the normal alone.
	const Vec3 plain = off_resting_paddle({}, config);
	CHECK(std::abs(plain.x) < 1e-12);
	CHECK(std::abs(plain.y) < 1e-12);

	// Spin about the paddle's normal has no slip at the contact point: nothing bends.
	const Vec3 about_normal = off_resting_paddle({ 0.0, 0.0, 50.0 }, config);
	CHECK(std::abs(about_normal.x) < 1e-12);
}
