// Four players (court.h): territories split by the diagonals, the side rotations of the
// four seats, one TERRITORY event per boundary crossed, back-wall owners, and contact with
// the paddles of players 2 and 3 (game-driven and on the device).

#include "pong/pong_test_support.h"

#include "renderers/pong/pong_sim.h"
#include "renderers/pong/pong_validation.h"

#include <doctest/doctest.h>

#include <cmath>
#include <vector>

using namespace haptics;
using namespace haptics::test;

namespace {

PongConfig four_player_config() {
	PongConfig config;
	config.players = 4;
	return config;
}

// Where each seat's back wall is, world: the direction from the centre.
constexpr Vec3 SEAT_DIRECTION[PONG_MAX_PLAYERS] = {
	{ 0.0, 0.0, 1.0 }, { 0.0, 0.0, -1.0 }, { 1.0, 0.0, 0.0 }, { -1.0, 0.0, 0.0 }
};

} // namespace

TEST_CASE("pong 4 players: the territory of points, on the diagonals and at the centre") {
	// Inside each triangle.
	CHECK(territory_of({ 0.3, 1.0, 2.0 }, 4) == 0);
	CHECK(territory_of({ -0.3, 1.0, -2.0 }, 4) == 1);
	CHECK(territory_of({ 2.0, 1.0, 0.3 }, 4) == 2);
	CHECK(territory_of({ -2.0, 1.0, -0.3 }, 4) == 3);
	// On the diagonals players 0 and 1 win the tie; the centre is player 0's, as z = 0 is in
	// the 2-player court.
	CHECK(territory_of({ 1.0, 0.0, 1.0 }, 4) == 0);
	CHECK(territory_of({ -1.0, 0.0, 1.0 }, 4) == 0);
	CHECK(territory_of({ 1.0, 0.0, -1.0 }, 4) == 1);
	CHECK(territory_of({ -1.0, 0.0, -1.0 }, 4) == 1);
	CHECK(territory_of({ 0.0, 0.0, 0.0 }, 4) == 0);
	// Just off a diagonal, the nearer back wall wins.
	CHECK(territory_of({ 1.0 + 1e-9, 0.0, 1.0 }, 4) == 2);
	CHECK(territory_of({ -1.0 - 1e-9, 0.0, -1.0 }, 4) == 3);
	// The 2-player court ignores x.
	CHECK(territory_of({ 2.0, 0.0, 0.3 }) == 0);
	CHECK(territory_of({ -2.0, 0.0, -0.3 }, 2) == 1);
	// Back walls: which side is whose goal.
	CHECK(back_wall_owner(CourtSurface::BACK_NEAR, 4) == 0);
	CHECK(back_wall_owner(CourtSurface::BACK_FAR, 4) == 1);
	CHECK(back_wall_owner(CourtSurface::RIGHT, 4) == 2);
	CHECK(back_wall_owner(CourtSurface::LEFT, 4) == 3);
	CHECK(back_wall_owner(CourtSurface::RIGHT, 2) == -1);
	CHECK(back_wall_owner(CourtSurface::CEILING, 4) == -1);
}

TEST_CASE("pong 4 players: each side rotation is orthonormal, turns about y, and points device forward at the centre") {
	const Vec3 axes[3] = { { 1.0, 0.0, 0.0 }, { 0.0, 1.0, 0.0 }, { 0.0, 0.0, 1.0 } };
	for (int player = 0; player < PONG_MAX_PLAYERS; ++player) {
		CAPTURE(player);
		Vec3 columns[3];
		for (int i = 0; i < 3; ++i) {
			columns[i] = side_rotation(player, axes[i]);
			CHECK(length(columns[i]) == doctest::Approx(1.0));
		}
		CHECK(dot(columns[0], columns[1]) == doctest::Approx(0.0));
		CHECK(dot(columns[0], columns[2]) == doctest::Approx(0.0));
		CHECK(dot(columns[1], columns[2]) == doctest::Approx(0.0));
		CHECK(dot(cross(columns[0], columns[1]), columns[2]) == doctest::Approx(1.0)); // A rotation, not a mirror.
		CHECK(columns[1] == Vec3{ 0.0, 1.0, 0.0 }); // About y: up stays up.
		// Sitting behind its back wall, forward (device -z) points from the seat at the centre.
		CHECK(side_rotation(player, PADDLE_FACING_DEVICE) == -SEAT_DIRECTION[player]);
		// Toward the user (device +z) points back at the seat.
		CHECK(side_rotation(player, axes[2]) == SEAT_DIRECTION[player]);
		const Vec3 v{ 0.3, -0.7, 1.9 };
		CHECK(side_rotation_inverse(player, side_rotation(player, v)) == v);
		CHECK(side_rotation(player, side_rotation_inverse(player, v)) == v);
		// The default input faces the centre.
		CHECK(default_pong_input().players[player].normal == -SEAT_DIRECTION[player]);
	}
	// Device right for player 2 (at +x, looking toward -x) is world -z.
	CHECK(side_rotation(2, axes[0]) == Vec3{ 0.0, 0.0, -1.0 });
	CHECK(side_rotation(3, axes[0]) == Vec3{ 0.0, 0.0, 1.0 });
}

TEST_CASE("pong 4 players: the court is square and a ball crossing each boundary raises exactly one territory event") {
	const PongConfig config = four_player_config();
	REQUIRE(validate_pong_config(config).ok());
	CHECK(court_half_x(config) == config.court_half_length_m);
	// Rolling (beginner: no gravity, no bounces) from inside one triangle into the next, for
	// every pair of neighbours and straight across.
	struct Crossing {
		Vec3 from;
		Vec3 to;
		int first;
		int second;
	};
	const double h = config.beginner_height_m;
	const Crossing crossings[] = {
		{ { 0.0, h, 1.0 }, { 1.0, h, 0.0 }, 0, 2 }, // 0 -> 2 across the +x+z diagonal
		{ { 1.0, h, 0.0 }, { 0.0, h, -1.0 }, 2, 1 },
		{ { 0.0, h, -1.0 }, { -1.0, h, 0.0 }, 1, 3 },
		{ { -1.0, h, 0.0 }, { 0.0, h, 1.0 }, 3, 0 },
		{ { 1.0, h, 0.5 }, { -1.0, h, 0.5 }, 2, 3 }, // Straight across, through player 0's tip.
	};
	for (const Crossing &crossing : crossings) {
		CAPTURE(crossing.first);
		CAPTURE(crossing.second);
		PongSim sim;
		sim.configure(config);
		PongInput input = idle_input();
		input.beginner = true;
		sim.set_input(input);
		// Fast enough that the air friction leaves it moving for the whole 2 s, slow enough that
		// it stays in the second territory.
		const Vec3 velocity = crossing.to - crossing.from;
		sim.apply(set_ball(crossing.from, velocity));
		REQUIRE(sim.territory() == crossing.first);
		std::vector<PongEvent> territory_events;
		for (int k = 0; k < 2000; ++k) {
			sim.step(PONG_DT, nullptr);
			for (const PongEvent &event : take_events(sim)) {
				if (event.type == PongEventType::TERRITORY) {
					territory_events.push_back(event);
				}
			}
		}
		if (crossing.first == 2 && crossing.second == 3) {
			// At z = 0.5 player 0's triangle spans |x| <= 0.5: 2 -> 0 -> 3, one event each.
			REQUIRE(territory_events.size() == 2);
			CHECK(territory_events[0].territory == 0);
			CHECK(territory_events[0].position.x == doctest::Approx(0.5).epsilon(0.01));
			CHECK(territory_events[1].territory == 3);
			CHECK(territory_events[1].position.x == doctest::Approx(-0.5).epsilon(0.01));
			continue;
		}
		REQUIRE(territory_events.size() == 1);
		CHECK(territory_events[0].territory == crossing.second);
		CHECK(territory_of(territory_events[0].position, 4) == crossing.second);
		CHECK(sim.territory() == crossing.second);
	}
}

TEST_CASE("pong 4 players: a back-wall bounce names whose goal it was") {
	const PongConfig config = four_player_config();
	const double l = config.court_half_length_m;
	for (int player = 0; player < PONG_MAX_PLAYERS; ++player) {
		CAPTURE(player);
		PongSim sim;
		sim.configure(config);
		PongInput input = idle_input();
		input.beginner = true;
		sim.set_input(input);
		const Vec3 dir = SEAT_DIRECTION[player];
		const Vec3 start = dir * (l - 0.5) + Vec3{ 0.0, config.beginner_height_m, 0.0 };
		sim.apply(set_ball(start, dir * 3.0));
		int walls = 0;
		for (int k = 0; k < 400; ++k) {
			sim.step(PONG_DT, nullptr);
			for (const PongEvent &event : take_events(sim)) {
				if (event.type == PongEventType::WALL) {
					++walls;
					CHECK(event.back_wall_of == player);
					CHECK(event.territory == player);
					CHECK(dot(event.position, dir) == doctest::Approx(l - config.ball_radius_m));
				}
			}
		}
		CHECK(walls == 1);
	}
	// With 2 players the side walls are nobody's goal (the court is narrower, too).
	PongSim sim;
	sim.set_input(idle_input());
	sim.apply(set_ball({ 1.0, 1.0, 0.5 }, { 3.0, 0.0, 0.0 }));
	bool saw_wall = false;
	for (int k = 0; k < 300 && !saw_wall; ++k) {
		sim.step(PONG_DT, nullptr);
		for (const PongEvent &event : take_events(sim)) {
			if (event.type == PongEventType::WALL) {
				saw_wall = true;
				CHECK(event.wall == CourtSurface::RIGHT);
				CHECK(event.back_wall_of == -1);
				CHECK(event.position.x == doctest::Approx(PongConfig{}.court_half_width_m - PongConfig{}.ball_radius_m));
			}
		}
	}
	CHECK(saw_wall);
}

TEST_CASE("pong 4 players: players 2 and 3 hit the ball, game-driven or on the device, and feel it toward themselves") {
	const PongConfig config = four_player_config();
	for (int player = 2; player < PONG_MAX_PLAYERS; ++player) {
		for (const bool device : { false, true }) {
			CAPTURE(player);
			CAPTURE(device);
			PongSim sim;
			sim.configure(config);
			PongInput input = idle_input();
			const Vec3 dir = SEAT_DIRECTION[player];
			const Vec3 avatar = dir * 2.0 + Vec3{ 0.0, 1.0, 0.0 };
			input.players[player] = game_paddle(avatar, -dir);
			input.players[player].kinematic = !device;
			input.local_player = device ? player : -1;
			sim.set_input(input);
			// Coming at the face from the centre, already 1 cm in.
			const Vec3 ball = avatar - dir * (config.ball_radius_m - 0.01);
			sim.apply(set_ball(ball, dir * 2.0));
			const HandSample hand;
			sim.step(PONG_DT, device ? &hand : nullptr);
			REQUIRE(sim.contact(player).touching);
			CHECK(dot(sim.ball_contact_force(), -dir) > 0.0); // Pushed back toward the centre.
			if (device) {
				const Vec3 force = sim.hand_forces().contact;
				CHECK(force.z > 0.0); // Device +z: toward the user.
				CHECK(force.z == doctest::Approx(config.hand_stiffness_n_per_m * sim.contact(player).penetration_m));
				CHECK(std::abs(force.x) < 1e-12);
			}
			// The rally goes on: the ball leaves toward the centre.
			for (int k = 0; k < 200; ++k) {
				sim.step(PONG_DT, device ? &hand : nullptr);
			}
			CHECK(dot(sim.ball().velocity, -dir) > 0.5);
			const std::vector<PongEvent> events = take_events(sim);
			bool paddle_event = false;
			for (const PongEvent &event : events) {
				paddle_event = paddle_event || (event.type == PongEventType::PADDLE && event.player == player);
			}
			CHECK(paddle_event);
		}
	}
	// In a 2-player court seats 2 and 3 do not exist: their paddles never touch the ball.
	PongSim sim;
	PongInput input = idle_input();
	const Vec3 avatar{ 1.0, 1.0, 0.0 };
	input.players[2] = game_paddle(avatar, { -1.0, 0.0, 0.0 });
	sim.set_input(input);
	sim.apply(set_ball(avatar - Vec3{ config.ball_radius_m - 0.01, 0.0, 0.0 }));
	sim.step(PONG_DT, nullptr);
	CHECK_FALSE(sim.contact(2).touching);
}

TEST_CASE("pong 4 players: the count is validated, and commands name players of the configured court") {
	PongConfig config;
	for (const int count : { 0, 1, 3, 5 }) {
		config.players = count;
		CHECK_FALSE(validate_pong_config(config).ok());
	}
	config.players = 4;
	CHECK(validate_pong_config(config).ok());
	PongCommand effect;
	effect.type = PongCommandType::EFFECT;
	effect.kind = PongEffectKind::REMOTE;
	effect.player = 3;
	effect.owner = 2;
	CHECK(validate_pong_command(effect, config).ok());
	config.players = 2;
	CHECK_FALSE(validate_pong_command(effect, config).ok());
	// A serve to the corner of the square court is inside only with 4 players.
	const PongCommand corner = set_ball({ 2.5, 1.0, 2.5 });
	CHECK_FALSE(validate_pong_command(corner, config).ok());
	config.players = 4;
	CHECK(validate_pong_command(corner, config).ok());
	PongInput input;
	input.local_player = 3;
	CHECK(validate_pong_input(input).ok());
	input.local_player = 4;
	CHECK_FALSE(validate_pong_input(input).ok());
}
