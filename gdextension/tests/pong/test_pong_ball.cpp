// The ball out of paddle contact (renderers/pong/ball.h): spin turned into deflection by the court's
// impulse bounces, the paper's air friction and speed cap, beginner mode's plane.

#include "pong/pong_test_support.h"

#include "renderers/pong/ball.h"
#include "renderers/pong/pong_sim.h"

#include <doctest/doctest.h>

#include <cmath>

using namespace haptics;
using namespace haptics::test;

namespace {

constexpr Vec3 FLOOR_NORMAL{ 0.0, 1.0, 0.0 };
constexpr Vec3 RIGHT_WALL_NORMAL{ -1.0, 0.0, 0.0 }; // x = +W, facing into the court.

// A floor bounce of v = (2, -3, 0) with spin w_z about z (rest speed 0: a real bounce).
BallState floor_bounce(double p_spin_z, const PongConfig &p_config) {
	BallState ball{ { 0.0, p_config.ball_radius_m, 0.0 }, { 2.0, -3.0, 0.0 }, { 0.0, 0.0, p_spin_z } };
	const Bounce bounce = bounce_off_plane(ball, FLOOR_NORMAL, p_config.restitution_court, p_config.surface_friction,
			p_config.ball_radius_m, 0.0);
	CHECK(bounce.bounced);
	CHECK(bounce.normal_speed == doctest::Approx(3.0));
	return ball;
}

} // namespace

TEST_CASE("pong ball: topspin speeds a floor bounce up, backspin slows it, as the impulse formulas say") {
	const PongConfig config;
	const double r = config.ball_radius_m;
	const double e = config.restitution_court;
	const double mu = config.surface_friction;
	// Every case below sticks: (2/7)|v_c| <= mu (1 + e) |v_n| = 0.35 x 1.85 x 3 = 1.94 m/s.
	const double limit = mu * (1.0 + e) * 3.0;
	struct Case {
		const char *name;
		double spin_z;
	};
	double speeds[3] = {};
	int index = 0;
	for (const Case &c : { Case{ "no spin", 0.0 }, Case{ "topspin", -60.0 }, Case{ "backspin", 60.0 } }) {
		CAPTURE(c.name);
		const BallState ball = floor_bounce(c.spin_z, config);
		// v_c = v_t + w x (-r n): along x, 2 + w_z r.
		const double slip = 2.0 + c.spin_z * r;
		REQUIRE(2.0 / 7.0 * std::abs(slip) <= limit);
		const double dv = -2.0 / 7.0 * slip;
		CHECK(ball.velocity.x == doctest::Approx(2.0 + dv));
		CHECK(ball.velocity.y == doctest::Approx(3.0 * e));
		CHECK(ball.velocity.z == doctest::Approx(0.0));
		// dw = -(5 / (2 r)) (n x dv_t): about z, +5 dv / (2 r).
		CHECK(ball.spin.z == doctest::Approx(c.spin_z + 5.0 * dv / (2.0 * r)));
		// Sticking means it leaves rolling: the contact point no longer slips.
		CHECK(ball.velocity.x + ball.spin.z * r == doctest::Approx(0.0).scale(1.0));
		speeds[index++] = ball.velocity.x;
	}
	CHECK(speeds[1] > 2.0); // Topspin: faster along its motion than it came in.
	CHECK(speeds[2] < speeds[0]); // Backspin: slower than without spin.
}

TEST_CASE("pong ball: side spin deflects a wall bounce along the wall, Coulomb-limited when strong") {
	const PongConfig config;
	const double r = config.ball_radius_m;
	const double e = config.restitution_wall;
	const double limit = config.surface_friction * (1.0 + e) * 3.0; // 1.995 m/s
	for (const double spin_y : { 50.0, 200.0 }) {
		CAPTURE(spin_y);
		BallState ball{ { 1.4, 1.0, 0.0 }, { 3.0, 0.0, 0.0 }, { 0.0, spin_y, 0.0 } };
		bounce_off_plane(ball, RIGHT_WALL_NORMAL, e, config.surface_friction, r, 0.0);
		// v_c = w x (-r n) = (0, w_y, 0) x (r, 0, 0) = (0, 0, -w_y r): the contact point
		// slips along -z, so friction pushes the ball along +z.
		const double slip = spin_y * r;
		const double dv = std::min(2.0 / 7.0 * slip, limit);
		CHECK(ball.velocity.x == doctest::Approx(-3.0 * e));
		CHECK(ball.velocity.z == doctest::Approx(dv));
		CHECK(ball.velocity.y == doctest::Approx(0.0));
		CHECK(ball.spin.y == doctest::Approx(spin_y - 5.0 * dv / (2.0 * r)));
	}
	// Without spin a square bounce stays square.
	BallState plain{ { 1.4, 1.0, 0.0 }, { 3.0, 0.0, 0.0 }, {} };
	bounce_off_plane(plain, RIGHT_WALL_NORMAL, e, config.surface_friction, r, 0.0);
	CHECK(plain.velocity.z == 0.0);
}

TEST_CASE("pong ball: in the court, topspin carries a floor bounce further along") {
	PongConfig config;
	double out[2] = {};
	for (int spun = 0; spun < 2; ++spun) {
		PongSim sim;
		sim.configure(config);
		sim.set_input(idle_input());
		// Falling onto the floor while moving along -z; topspin for that motion is about -x.
		const Vec3 spin{ spun ? -60.0 : 0.0, 0.0, 0.0 };
		sim.apply(set_ball({ 0.0, 0.5, 1.5 }, { 0.0, 0.0, -2.0 }, spin));
		for (int k = 0; k < 1000 && out[spun] == 0.0; ++k) {
			sim.step(PONG_DT, nullptr);
			for (const PongEvent &event : take_events(sim)) {
				if (event.type == PongEventType::FLOOR) {
					out[spun] = -sim.ball().velocity.z;
				}
			}
		}
	}
	MESSAGE("speed along the court after the bounce: plain " << out[0] << " m/s, topspin " << out[1] << " m/s");
	REQUIRE(out[0] > 0.0);
	CHECK(out[1] > out[0] + 0.3);
}

TEST_CASE("pong ball: air friction takes a_lin t off |v| and a_ang t off |w|, never below zero") {
	PongConfig config;
	config.gravity_m_per_s2 = 0.0;
	config.court_half_length_m = 20.0; // Room to fly for a second.
	PongSim sim;
	sim.configure(config);
	sim.set_input(idle_input());
	const Vec3 velocity{ 1.2, 0.0, -2.4 };
	const Vec3 spin{ 0.0, 30.0, 40.0 };
	sim.apply(set_ball({ 0.0, 1.0, 10.0 }, velocity, spin));
	for (int k = 0; k < 1000; ++k) {
		sim.step(PONG_DT, nullptr);
	}
	const double t = 1.0;
	CHECK(length(sim.ball().velocity) == doctest::Approx(length(velocity) - config.air_linear_decel_m_per_s2 * t));
	CHECK(length(sim.ball().spin) == doctest::Approx(length(spin) - config.air_angular_decel_rad_per_s2 * t));
	// The direction is kept: a decrease of the magnitude, not a drag on each axis.
	CHECK(sim.ball().velocity.x / sim.ball().velocity.z == doctest::Approx(velocity.x / velocity.z));
	CHECK(sim.ball().spin.y / sim.ball().spin.z == doctest::Approx(spin.y / spin.z));

	CHECK(decrease_length({ 0.3, 0.0, 0.4 }, 0.6) == Vec3{});
	const Vec3 slower = decrease_length({ 0.3, 0.0, 0.4 }, 0.1);
	CHECK(length(slower) == doctest::Approx(0.4));
	// A slow ball stops and stays stopped.
	sim.apply(set_ball({ 0.0, 1.0, 10.0 }, { 0.0, 0.0, -0.3 }));
	for (int k = 0; k < 1000; ++k) {
		sim.step(PONG_DT, nullptr);
	}
	CHECK(sim.ball().velocity == Vec3{});
	CHECK(sim.ball().position.z == doctest::Approx(10.0 - 0.3 * 0.3 / (2.0 * config.air_linear_decel_m_per_s2)).epsilon(1e-3));
}

TEST_CASE("pong ball: the speed cap holds for a serve and for a hard swing") {
	PongConfig config;
	config.gravity_m_per_s2 = 0.0;
	PongSim sim;
	sim.configure(config);
	PongInput input = idle_input();
	sim.set_input(input);
	sim.apply(set_ball({ 0.0, 1.0, 0.5 }, { 0.0, 0.0, -30.0 }, { 500.0, 0.0, 0.0 }));
	CHECK(length(sim.ball().velocity) == doctest::Approx(config.max_ball_speed_m_per_s));
	CHECK(length(sim.ball().spin) == doctest::Approx(config.max_spin_rad_per_s));

	// A paddle swung at 8 m/s would send the ball off at ~15 m/s: the cap holds it at 9.
	sim.apply(set_ball({ 0.0, 1.0, 1.0 }));
	const Vec3 normal{ 0.0, 0.0, -1.0 };
	const Vec3 paddle_velocity{ 0.0, 0.0, -8.0 };
	const Vec3 start{ 0.0, 1.0, 1.0 + config.ball_radius_m + 0.01 };
	double fastest = 0.0;
	for (int k = 0; k < 300; ++k) {
		input.players[0] = game_paddle(start + paddle_velocity * (k * PONG_DT), normal, paddle_velocity);
		sim.set_input(input);
		sim.step(PONG_DT, nullptr);
		fastest = std::max(fastest, length(sim.ball().velocity));
	}
	CHECK(fastest == doctest::Approx(config.max_ball_speed_m_per_s));
}

TEST_CASE("pong ball: beginner mode holds the ball in its plane whatever pushes it") {
	PongConfig config;
	PongSim sim;
	sim.configure(config);
	PongInput input = idle_input();
	input.beginner = true;
	// A paddle tilted 45 degrees up: its push has a vertical part that must be dropped.
	const Vec3 normal = normalized_or_zero({ 0.0, 1.0, -1.0 });
	input.players[0] = game_paddle({ 0.0, config.beginner_height_m, 1.0 }, normal);
	sim.set_input(input);
	sim.apply(set_ball({ 0.0, config.beginner_height_m, 1.0 - 0.05 }));
	for (int k = 0; k < 2000; ++k) {
		sim.step(PONG_DT, nullptr);
		REQUIRE(sim.ball().position.y == config.beginner_height_m);
		REQUIRE(sim.ball().velocity.y == 0.0);
		if (k == 200) { // Off the paddle, not yet at the far wall.
			CHECK_FALSE(sim.contact(0).touching);
			CHECK(sim.ball().velocity.z < -0.5); // Pushed away in its plane, not up.
		}
	}
}
