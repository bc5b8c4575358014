// The simulation as a whole (renderers/pong/pong_sim.h): a ball settling on a held paddle, the events,
// the paddles' poses from the device on either side, and the extrapolation of game-driven
// paddles and walking avatars.

#include "pong/pong_test_support.h"

#include "renderers/pong/pong_sim.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <vector>

using namespace haptics;
using namespace haptics::test;

namespace {

constexpr Vec3 UP{ 0.0, 1.0, 0.0 };

// Kinetic + gravitational + the contact spring's potential energy, over a horizontal paddle
// at rest at height p_paddle_y.
double energy(const PongSim &p_sim, const PongConfig &p_config, double p_paddle_y) {
	const BallState &ball = p_sim.ball();
	const double m = p_config.ball_mass_kg;
	const double delta = std::max(0.0, p_config.ball_radius_m - (ball.position.y - p_paddle_y));
	return 0.5 * m * length_squared(ball.velocity) + m * p_config.gravity_m_per_s2 * ball.position.y +
			0.5 * p_config.ball_stiffness_n_per_m * delta * delta;
}

// The ball dropped from p_drop onto the floor: the first FLOOR event within 3 s, if any.
std::optional<PongEvent> first_floor_event(const Vec3 &p_drop) {
	PongSim sim;
	sim.set_input(idle_input());
	sim.apply(set_ball(p_drop));
	for (int k = 0; k < 3000; ++k) {
		sim.step(PONG_DT, nullptr);
		for (const PongEvent &event : take_events(sim)) {
			if (event.type == PongEventType::FLOOR) {
				return event;
			}
		}
	}
	return std::nullopt;
}

} // namespace

TEST_CASE("pong sim: a ball dropped on a held horizontal paddle settles, its energy never rising") {
	const PongConfig config;
	PongSim sim;
	PongInput input = idle_input();
	const Vec3 paddle{ 0.0, 1.0, 1.0 };
	input.players[0] = game_paddle(paddle, UP);
	sim.set_input(input);
	sim.apply(set_ball(paddle + Vec3{ 0.0, config.ball_radius_m + 0.02, 0.0 })); // 2 cm above.
	const double start = energy(sim, config, paddle.y);
	double highest = start;
	double largest_rise = 0.0;
	double previous = start;
	for (int k = 0; k < 3000; ++k) {
		sim.step(PONG_DT, nullptr);
		const double e = energy(sim, config, paddle.y);
		highest = std::max(highest, e);
		largest_rise = std::max(largest_rise, e - previous);
		previous = e;
	}
	const double speed = length(sim.ball().velocity - sim.paddle(0).velocity);
	const double drop = config.ball_mass_kg * config.gravity_m_per_s2 * 0.02; // The energy it fell with.
	MESSAGE("after 3 s: relative speed " << speed * 1e3 << " mm/s; energy above the start at most " << (highest - start)
										 << " J, largest one-tick rise " << largest_rise << " J (drop energy " << drop
										 << " J)");
	CHECK(sim.contact(0).touching);
	CHECK(speed < 1e-3);
	// Semi-implicit Euler's energy wobbles by about omega_n dt / 2 of the contact's energy
	// within a tick; it must never build up.
	CHECK(highest - start <= 0.05 * drop);
	CHECK(largest_rise <= 0.05 * drop);
	// At rest on the spring: k delta = m g.
	CHECK(sim.contact(0).penetration_m ==
			doctest::Approx(config.ball_mass_kg * config.gravity_m_per_s2 / config.ball_stiffness_n_per_m).epsilon(1e-3));
}

TEST_CASE("pong sim: floor bounces say whose territory, crossing z = 0 says the new one, rolling says nothing") {
	const PongConfig config;
	const std::optional<PongEvent> near = first_floor_event({ 0.3, 1.0, 1.0 });
	REQUIRE(near);
	CHECK(near->territory == 0);
	CHECK(near->position.y == doctest::Approx(config.ball_radius_m));
	// Falling, the ball gains g and loses the air's a_lin every second.
	const double fall = 1.0 - config.ball_radius_m;
	const double net = config.gravity_m_per_s2 - config.air_linear_decel_m_per_s2;
	CHECK(near->speed == doctest::Approx(std::sqrt(2.0 * net * fall)).epsilon(0.01));
	const std::optional<PongEvent> far = first_floor_event({ -0.3, 1.0, -1.0 });
	REQUIRE(far);
	CHECK(far->territory == 1);

	// Flying from player 0's half into player 1's.
	PongSim sim;
	sim.set_input(idle_input());
	sim.apply(set_ball({ 0.0, 1.5, 0.3 }, { 0.0, 1.0, -3.0 }));
	std::vector<PongEvent> events;
	for (int k = 0; k < 200; ++k) {
		sim.step(PONG_DT, nullptr);
		for (const PongEvent &event : take_events(sim)) {
			events.push_back(event);
		}
	}
	REQUIRE(count_events(events, PongEventType::TERRITORY) == 1);
	const PongEvent &crossing = events[0];
	CHECK(crossing.type == PongEventType::TERRITORY);
	CHECK(crossing.territory == 1);
	CHECK(crossing.position.z < 0.0);
	CHECK(crossing.position.z > -0.01);

	// Rolling along the floor, and a drop too soft to be a bounce: no FLOOR event.
	PongSim rolling;
	rolling.set_input(idle_input());
	rolling.apply(set_ball({ -1.0, config.ball_radius_m, 1.0 }, { 1.0, 0.0, 0.0 }));
	for (int k = 0; k < 1000; ++k) {
		rolling.step(PONG_DT, nullptr);
	}
	const std::vector<PongEvent> rolled = take_events(rolling);
	CHECK(rolled.empty());
	CHECK(rolling.ball().position.x > -1.0 + 0.3); // It did roll.
	const double soft_drop = 0.5 * config.min_bounce_speed_m_per_s * config.min_bounce_speed_m_per_s /
			config.gravity_m_per_s2; // The height whose landing speed is the threshold.
	CHECK_FALSE(first_floor_event({ 0.0, config.ball_radius_m + 0.8 * soft_drop, 1.0 }));
}

TEST_CASE("pong sim: wall and paddle events name the wall, the player and the speeds") {
	PongConfig config;
	config.air_linear_decel_m_per_s2 = 0.0; // Speeds stay round numbers.
	PongSim sim;
	sim.configure(config);
	PongInput input = idle_input();
	input.beginner = true; // No gravity, a horizontal plane: nothing but the walls and paddle.
	input.players[1] = game_paddle({ 0.0, config.beginner_height_m, -2.0 }, { 0.0, 0.0, 1.0 });
	sim.set_input(input);
	sim.apply(set_ball({ 0.0, config.beginner_height_m, -1.0 }, { 0.0, 0.0, -2.0 }));
	std::vector<PongEvent> events;
	for (int k = 0; k < 6000 && count_events(events, PongEventType::WALL) == 0; ++k) {
		sim.step(PONG_DT, nullptr);
		for (const PongEvent &event : take_events(sim)) {
			events.push_back(event);
		}
	}
	REQUIRE(count_events(events, PongEventType::PADDLE) == 1);
	REQUIRE(count_events(events, PongEventType::RELEASE) == 1);
	CHECK(events[0].type == PongEventType::PADDLE);
	CHECK(events[0].player == 1);
	CHECK(events[0].speed == doctest::Approx(2.0).epsilon(0.01)); // Closing speed: the ball's.
	CHECK(events[1].type == PongEventType::RELEASE);
	CHECK(events[1].player == 1);
	CHECK(events[1].speed > 1.2); // It springs back off the paddle at rest.
	CHECK(events[1].speed < 2.0);
	const PongEvent &wall = events.back();
	CHECK(wall.type == PongEventType::WALL);
	CHECK(wall.wall == CourtSurface::BACK_NEAR); // Back across the court to player 0's wall.
	CHECK(wall.position.z == doctest::Approx(config.court_half_length_m - config.ball_radius_m));
	PongState state;
	sim.fill_state(state);
	CHECK(state.paddle_contacts == 1);
	CHECK(state.bounces == 1);
}

TEST_CASE("pong sim: the device paddle is avatar + side rotation of the stylus times the workspace scale") {
	const PongConfig config;
	for (int player = 0; player < 2; ++player) {
		CAPTURE(player);
		PongSim sim;
		PongInput input = idle_input();
		input.local_player = player;
		input.players[player].avatar = { 0.2, 1.0, player == 0 ? 2.0 : -2.0 };
		input.players[player].normal = { 0.0, 0.6, 0.8 };
		sim.set_input(input);
		HandSample hand;
		hand.position_m = { 0.02, -0.01, 0.03 };
		hand.velocity_m_per_s = { 0.1, 0.2, -0.3 };
		sim.step(PONG_DT, &hand);
		const PaddlePose &pose = sim.paddle(player);
		const double sign = player == 0 ? 1.0 : -1.0; // Player 1: device x, z are world -x, -z.
		const double s = config.workspace_scale;
		CHECK(pose.center.x == doctest::Approx(0.2 + sign * 0.02 * s));
		CHECK(pose.center.y == doctest::Approx(1.0 - 0.01 * s));
		CHECK(pose.center.z == doctest::Approx(input.players[player].avatar.z + sign * 0.03 * s));
		CHECK(pose.velocity.x == doctest::Approx(sign * 0.1 * s));
		CHECK(pose.velocity.y == doctest::Approx(0.2 * s));
		CHECK(pose.velocity.z == doctest::Approx(-sign * 0.3 * s));
		CHECK(pose.normal.y == doctest::Approx(0.6)); // No orientation: the game's normal.

		// With an orientation: a quarter turn about y points the paddle's face (device -z) at
		// device -x, which is world -x for player 0 and world +x for player 1.
		hand.has_orientation = true;
		const double half = 0.25 * std::numbers::pi;
		hand.orientation = Orientation{ std::cos(half), 0.0, std::sin(half), 0.0 };
		sim.step(PONG_DT, &hand);
		CHECK(sim.paddle(player).normal.x == doctest::Approx(-sign));
		CHECK(std::abs(sim.paddle(player).normal.z) < 1e-12);
	}
	CHECK(rotate(Orientation{}, PADDLE_FACING_DEVICE) == PADDLE_FACING_DEVICE);
	CHECK(side_rotation(1, side_rotation(1, { 1.0, 2.0, 3.0 })) == Vec3{ 1.0, 2.0, 3.0 });
	CHECK(default_pong_input().players[1].normal == Vec3{ 0.0, 0.0, 1.0 }); // Facing the opponent.
}

TEST_CASE("pong sim: game-driven paddles and walking avatars are extrapolated for 50 ms at most") {
	PongSim sim;
	PongInput input = idle_input();
	input.local_player = 0;
	input.players[0].avatar = { 0.0, 1.0, 2.0 };
	input.players[1] = game_paddle({ 0.0, 1.0, -2.0 }, { 0.0, 0.0, 1.0 }, { 1.0, 0.0, 0.0 });
	sim.set_input(input);
	const HandSample hand;
	for (int k = 0; k < 20; ++k) {
		sim.step(PONG_DT, &hand);
	}
	CHECK(sim.paddle(1).center.x == doctest::Approx(0.02)); // 20 ms at 1 m/s.
	for (int k = 0; k < 100; ++k) {
		sim.step(PONG_DT, &hand);
	}
	CHECK(sim.paddle(1).center.x == doctest::Approx(PONG_MAX_EXTRAPOLATION_S)); // Then it holds.

	// The device player's avatar walks at 2 m/s in 60 Hz steps: between inputs the paddle
	// moves on smoothly instead of jumping at each frame.
	double largest_step = 0.0;
	double previous = sim.paddle(0).center.x;
	for (int frame = 1; frame <= 30; ++frame) {
		input.players[0].avatar.x = 2.0 * frame / 60.0;
		sim.set_input(input);
		for (int k = 0; k < 17; ++k) { // ~1 kHz / 60 Hz
			sim.step(PONG_DT, &hand);
			const double x = sim.paddle(0).center.x;
			if (frame > 2) {
				largest_step = std::max(largest_step, std::abs(x - previous));
			}
			previous = x;
		}
	}
	MESSAGE("largest paddle step per tick while the avatar walks: " << largest_step * 1e3 << " mm");
	CHECK(largest_step < 0.005); // Without extrapolation: 33 mm once a frame.
	// A teleport is not a walk: no flying off at 100 m/s.
	input.players[0].avatar.x = -1.0;
	sim.set_input(input);
	sim.step(PONG_DT, &hand);
	sim.step(PONG_DT, &hand);
	CHECK(sim.paddle(0).center.x == doctest::Approx(-1.0));
}

TEST_CASE("pong sim: a ball hitting either player's paddle face pushes that hand toward its user") {
	const PongConfig config;
	for (int player = 0; player < 2; ++player) {
		CAPTURE(player);
		PongSim sim;
		PongInput input = idle_input();
		input.local_player = player;
		const double side = player == 0 ? 1.0 : -1.0; // Player 0 at +z, player 1 at -z.
		input.players[player].avatar = { 0.0, 1.0, side * 2.0 };
		input.players[player].active = true;
		input.players[player].normal = { 0.0, 0.0, -side }; // Facing the opponent.
		sim.set_input(input);
		// Coming at the face from the opponent's side, already 1 cm in.
		const Vec3 ball{ 0.0, 1.0, side * (2.0 - config.ball_radius_m + 0.01) };
		sim.apply(set_ball(ball, { 0.0, 0.0, side * 2.0 }));
		const HandSample hand;
		sim.step(PONG_DT, &hand);
		REQUIRE(sim.contact(player).touching);
		const Vec3 force = sim.hand_forces().contact;
		CHECK(force.z > 0.0); // Device +z: toward the user, whichever side.
		CHECK(force.z == doctest::Approx(config.hand_stiffness_n_per_m * sim.contact(player).penetration_m));
		CHECK(std::abs(force.x) < 1e-12);
		CHECK(std::abs(force.y) < 1e-12);
	}
}

TEST_CASE("pong sim: a remote paddle's pose age carries it on by its velocity, at most 150 ms") {
	PongSim sim;
	PongInput input = idle_input();
	input.local_player = 0;
	input.players[0].avatar = { 0.0, 1.0, 2.0 };
	input.players[1] = game_paddle({ 0.0, 1.0, -2.0 }, { 0.0, 0.0, 1.0 }, { 1.0, 0.0, 0.0 });
	input.players[1].pose_age_s = 0.1;
	sim.set_input(input);
	const HandSample hand;
	sim.step(PONG_DT, &hand);
	// 100 ms of age plus the tick since the input, at 1 m/s.
	CHECK(sim.paddle(1).center.x == doctest::Approx(0.101));
	input.players[1].pose_age_s = 2.0; // A stalled stream: held at the cap.
	sim.set_input(input);
	sim.step(PONG_DT, &hand);
	CHECK(sim.paddle(1).center.x == doctest::Approx(PONG_MAX_POSE_EXTRAPOLATION_S + 0.001));
	CHECK(sim.paddle(1).velocity.x == doctest::Approx(1.0));
}
