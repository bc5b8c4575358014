// Pong through the engine (HapticsSystem, the simulated device, RenderMode::PONG, manual
// steps): the hand feels the ball land along the paddle's normal, within the device's limit;
// the input is the watchdog's heartbeat; commands wait for the mode switch; bad input is
// refused by name and changes nothing; forces stay finite under anything valid.

#include "pong/pong_test_support.h"

#include "core/servo/telemetry.h"
#include "renderers/pong/pong_port.h"
#include "renderers/pong/pong_renderer.h"
#include "system/haptics_system.h"
#include "system/settings_validation.h"
#include "system_config.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

using namespace haptics;
using namespace haptics::test;

namespace {

constexpr double NaN = std::numeric_limits<double>::quiet_NaN();

// Player 0 holds the device paddle flat (facing up) at its avatar; player 1 is out of play.
PongInput flat_paddle_input() {
	PongInput input;
	input.local_player = 0;
	input.players[0].avatar = { 0.0, 1.0, 2.0 };
	input.players[0].normal = { 0.0, 1.0, 0.0 };
	input.players[1].active = false;
	return input;
}

void start_pong(HapticsSystem &r_system) {
	REQUIRE(r_system.open_simulated_device());
	REQUIRE(r_system.set_hand_target({ 0.0, 0.0, 0.0 }));
	REQUIRE(reconfigure(r_system, [](RenderConfig &r_config) { r_config.servo.render_mode = RenderMode::PONG; }));
}

// The engine's Pong renderer, as the game reaches it.
PongPort pong(HapticsSystem &r_system) {
	return PongPort(r_system.renderers().pong.channels);
}

bool mentions(const Status &p_status, const char *p_text) {
	return std::strstr(p_status.message(), p_text) != nullptr;
}

bool same_state(const PongState &p_a, const PongState &p_b) {
	return std::memcmp(&p_a, &p_b, sizeof(PongState)) == 0;
}

} // namespace

TEST_CASE("pong system: a ball landing on the paddle pushes the hand along the paddle normal, within the limit") {
	HapticsSystem system;
	start_pong(system);
	const PongInput input = flat_paddle_input();
	REQUIRE(pong(system).set_input(input));
	REQUIRE(pong(system).push_command(set_ball({ 0.0, 1.4, 2.0 })));
	const double limit = system.device_limits().max_force_n;
	double strongest = 0.0;
	int contact_ticks = 0;
	std::vector<PongEvent> events(PONG_EVENT_QUEUE_CAPACITY);
	size_t paddle_events = 0;
	for (int k = 0; k < 3000; ++k) {
		if (k % 16 == 0) {
			REQUIRE(pong(system).set_input(input)); // A 60 Hz game.
		}
		REQUIRE(system.step(0.001));
		const ForceComponents forces = system.forces();
		const PongState state = pong(system).state();
		REQUIRE(is_finite(forces.total));
		REQUIRE(length(forces.total) <= limit + 1e-12);
		strongest = std::max(strongest, length(forces.total));
		if (state.in_contact[0] && length(forces.parts[CONTACT_FORCE]) > 0.05) {
			++contact_ticks;
			// Down: the ball presses the flat paddle, and player 0's device frame is the world's.
			CHECK(forces.parts[CONTACT_FORCE].y < 0.0);
			CHECK(std::abs(forces.parts[CONTACT_FORCE].x) < 1e-9);
			CHECK(std::abs(forces.parts[CONTACT_FORCE].z) < 1e-9);
			CHECK(state.hand_force.contact == forces.parts[CONTACT_FORCE]);
			CHECK((system.output().flags & TELEMETRY_FLAG_PADDLE_CONTACT) != 0u);
		}
		const size_t count = pong(system).drain_events(events.data(), events.size());
		for (size_t e = 0; e < count; ++e) {
			paddle_events += events[e].type == PongEventType::PADDLE && events[e].player == 0 ? 1 : 0;
		}
	}
	MESSAGE("strongest hand force " << strongest << " N over " << contact_ticks << " contact ticks");
	CHECK(contact_ticks > 100);
	CHECK(paddle_events >= 1);
	CHECK(strongest > 0.3); // Felt, not a rounding error.
	CHECK_FALSE(system.stats().watchdog_tripped);
	const PongState state = pong(system).state();
	CHECK(state.paddle_contacts >= 1);
	CHECK(state.ball_position.y > 1.0); // Still on the paddle.
	CHECK((system.output().flags & TELEMETRY_FLAG_PONG_MODE) != 0u);
}

TEST_CASE("pong system: before the game's first input no paddle plays and the hand feels nothing") {
	HapticsSystem system;
	start_pong(system);
	std::vector<PongEvent> events(PONG_EVENT_QUEUE_CAPACITY);
	for (int k = 0; k < 500; ++k) {
		REQUIRE(system.step(0.001));
		CHECK(pong(system).drain_events(events.data(), events.size()) == 0);
	}
	CHECK(system.forces().continuous == Vec3{});
	const PongState state = pong(system).state();
	CHECK(state.paddle_contacts == 0);
	CHECK_FALSE(state.in_contact[0]);
	CHECK(length(state.ball_velocity) < 1e-9); // At rest on the centre spot.
	CHECK(state.ball_position.y == doctest::Approx(PongConfig{}.ball_radius_m));
}

TEST_CASE("pong system: the input is the watchdog's heartbeat in pong mode") {
	HapticsSystem system;
	start_pong(system);
	REQUIRE(pong(system).set_input(flat_paddle_input()));
	for (int k = 0; k < 300; ++k) {
		if (k % 16 == 0) {
			REQUIRE(pong(system).set_input(flat_paddle_input()));
		}
		REQUIRE(system.step(0.001));
	}
	CHECK_FALSE(system.stats().watchdog_tripped);
	CHECK(system.stats().frames_received == 0); // No frames at all: the input kept it alive.
	for (int k = 0; k < 300; ++k) {
		REQUIRE(system.step(0.001));
	}
	CHECK(system.stats().watchdog_tripped); // The game went quiet.
}

TEST_CASE("pong system: a serve sent before the switch to pong is not lost, and the state shows it") {
	HapticsSystem system;
	REQUIRE(system.open_simulated_device());
	REQUIRE(pong(system).push_command(set_ball({ 0.5, 1.5, -1.0 }, { 0.0, 0.0, 1.0 })));
	REQUIRE(system.step(0.001)); // Movement mode: the command is taken, the ball waits.
	PongState state = pong(system).state();
	CHECK(state.ball_position == Vec3{ 0.5, 1.5, -1.0 });
	CHECK(state.territory == 1);
	REQUIRE(reconfigure(system, [](RenderConfig &r_config) { r_config.servo.render_mode = RenderMode::PONG; }));
	REQUIRE(system.step(0.001));
	state = pong(system).state();
	CHECK(state.ball_position.z > -1.0); // It flies on from where it was served.
	CHECK(state.ball_position.z < -0.99);
}

TEST_CASE("pong system: bad input and commands are refused by name and change nothing") {
	HapticsSystem system;
	HapticsSystem twin; // Gets only the good calls: the states must stay identical.
	start_pong(system);
	start_pong(twin);
	const PongInput good = flat_paddle_input();
	REQUIRE(pong(system).set_input(good));
	REQUIRE(pong(twin).set_input(good));
	REQUIRE(pong(system).push_command(set_ball({ 0.0, 1.4, 2.0 })));
	REQUIRE(pong(twin).push_command(set_ball({ 0.0, 1.4, 2.0 })));

	PongInput bad = good;
	bad.players[1].avatar.y = NaN;
	Status status = pong(system).set_input(bad);
	CHECK(status.code() == StatusCode::INVALID_ARGUMENT);
	CHECK(mentions(status, "PongInput.players[1].avatar"));
	bad = good;
	bad.players[0].normal = { NaN, 0.0, 0.0 };
	status = pong(system).set_input(bad);
	CHECK(mentions(status, "PongInput.players[0].normal: not finite"));
	bad = good;
	bad.local_player = 4;
	CHECK(mentions(pong(system).set_input(bad), "PongInput.local_player: 4 is outside [-1, 3]"));
	bad = good;
	bad.players[0].paddle_velocity.z = std::numeric_limits<double>::infinity();
	CHECK_FALSE(pong(system).set_input(bad));

	status = pong(system).push_command(set_ball({ 0.0, NaN, 0.0 }));
	CHECK(status.code() == StatusCode::INVALID_ARGUMENT);
	CHECK(mentions(status, "PongCommand.position: not finite"));
	CHECK(mentions(pong(system).push_command(set_ball({ 0.0, 1.0, 9.0 })), "outside the court"));
	CHECK(mentions(pong(system).push_command(set_ball({ 0.0, 1.0, 0.0 }, { NaN, 0.0, 0.0 })), "PongCommand.velocity"));
	PongCommand effect;
	effect.type = PongCommandType::EFFECT;
	effect.kind = PongEffectKind::RECOIL;
	CHECK(mentions(pong(system).push_command(effect), "PongCommand.direction: zero length"));
	effect.direction = { 1.0, 0.0, 0.0 };
	effect.magnitude_n = NaN;
	effect.use_default_magnitude = false;
	CHECK(mentions(pong(system).push_command(effect), "PongCommand.magnitude_n: not finite"));
	effect.use_default_magnitude = true;
	effect.magnitude_n = 0.0;
	effect.player = 2; // A seat of a 4-player court, not of this 2-player one.
	CHECK(mentions(pong(system).push_command(effect), "PongCommand.player must be 0..1 on this court"));
	effect.player = 0;
	effect.kind = PongEffectKind::REMOTE;
	effect.owner = 0;
	CHECK(mentions(pong(system).push_command(effect), "PongCommand.owner must be another player"));
	effect.kind = static_cast<PongEffectKind>(17);
	CHECK(mentions(pong(system).push_command(effect), "PongCommand.kind: 17 is none of the 6 values"));

	for (int k = 0; k < 1500; ++k) {
		if (k % 16 == 0) {
			REQUIRE(pong(system).set_input(good));
			REQUIRE(pong(twin).set_input(good));
		}
		REQUIRE(system.step(0.001));
		REQUIRE(twin.step(0.001));
	}
	CHECK(same_state(pong(system).state(), pong(twin).state()));
	CHECK(pong(system).state().paddle_contacts >= 1);
}

TEST_CASE("pong system: forces stay finite and within the limit under anything valid") {
	HapticsSystem system;
	start_pong(system);
	const double limit = system.device_limits().max_force_n;
	const PongConfig config;
	uint64_t seed = 12345;
	auto uniform = [&seed](double p_low, double p_high) {
		seed = seed * 6364136223846793005ull + 1442695040888963407ull;
		return p_low + (p_high - p_low) * static_cast<double>(seed >> 11) / 9007199254740992.0;
	};
	auto random_vector = [&uniform](double p_size) {
		return Vec3{ uniform(-p_size, p_size), uniform(-p_size, p_size), uniform(-p_size, p_size) };
	};
	for (int k = 0; k < 5000; ++k) {
		if (k % 10 == 0) {
			PongInput input;
			input.local_player = static_cast<int32_t>(std::floor(uniform(-1.0, 2.0)));
			input.beginner = uniform(0.0, 1.0) < 0.2;
			for (PongPlayerInput &player : input.players) {
				player.avatar = { uniform(-1.5, 1.5), uniform(0.0, 2.5), uniform(-3.0, 3.0) };
				player.paddle_offset = random_vector(0.5);
				player.paddle_velocity = random_vector(20.0);
				player.normal = random_vector(1.0) + Vec3{ 0.0, 0.0, 1e-3 };
				player.spin = uniform(0.0, 1.0) < 0.5;
				player.gun = uniform(0.0, 1.0) < 0.1;
			}
			REQUIRE(pong(system).set_input(input));
			REQUIRE(system.set_hand_target(random_vector(0.12)));
		}
		if (k % 50 == 0) {
			const Vec3 inside{ uniform(-1.4, 1.4), uniform(0.1, 2.4), uniform(-2.9, 2.9) };
			REQUIRE(pong(system).push_command(set_ball(inside, random_vector(50.0), random_vector(500.0))));
		}
		if (k % 70 == 0) {
			PongCommand effect;
			effect.type = PongCommandType::EFFECT;
			effect.player = static_cast<int32_t>(uniform(0.0, 2.0));
			effect.owner = 1 - effect.player;
			effect.kind = static_cast<PongEffectKind>(static_cast<int>(uniform(0.0, 6.0)));
			effect.direction = random_vector(1.0) + Vec3{ 1e-3, 0.0, 0.0 };
			REQUIRE(pong(system).push_command(effect));
		}
		REQUIRE(system.step(0.001));
		const ForceComponents forces = system.forces();
		REQUIRE(is_finite(forces.continuous));
		REQUIRE(is_finite(forces.total));
		REQUIRE(length(forces.total) <= limit + 1e-12);
		const PongState state = pong(system).state();
		REQUIRE(is_finite(state.ball_position));
		REQUIRE(length(state.ball_velocity) <= config.max_ball_speed_m_per_s + 1e-9);
	}
	CHECK(system.stats().non_finite_ticks == 0);
}

TEST_CASE("pong system: events past the queue's capacity are dropped and counted") {
	HapticsSystem system;
	start_pong(system);
	// The ball shuttles between the side walls of a narrow court forever, never drained.
	REQUIRE(reconfigure(system, [](RenderConfig &r_config) {
		r_config.pong.court_half_width_m = 0.5;
		r_config.pong.beginner_target_half_width_m = 0.5;
		r_config.pong.restitution_wall = 1.0;
		r_config.pong.air_linear_decel_m_per_s2 = 0.0;
	}));
	PongInput input = flat_paddle_input();
	input.players[0].active = false;
	input.beginner = true;
	const double height = PongConfig{}.beginner_height_m;
	REQUIRE(pong(system).push_command(set_ball({ 0.0, height, 1.0 }, { 9.0, 0.0, 0.0 })));
	for (int k = 0; k < 60000; ++k) {
		if (k % 16 == 0) {
			REQUIRE(pong(system).set_input(input));
		}
		REQUIRE(system.step(0.001));
		if (pong(system).state().events_dropped > 0) {
			break;
		}
	}
	const PongState state = pong(system).state();
	CHECK(state.events_dropped > 0);
	std::vector<PongEvent> events(2 * PONG_EVENT_QUEUE_CAPACITY);
	CHECK(pong(system).drain_events(events.data(), events.size()) == PONG_EVENT_QUEUE_CAPACITY);
	CHECK(events[0].type == PongEventType::WALL);
	CHECK(pong(system).drain_events(nullptr, 4) == 0);
}

TEST_CASE("pong system: the pong config section validates its joint limits by name") {
	RenderConfig config;
	CHECK(validate_render_config(config));
	config.pong.beginner_height_m = 2.45; // The ball would poke through the 2.5 m ceiling.
	Status status = validate_render_config(config);
	CHECK(status.code() == StatusCode::OUT_OF_RANGE);
	CHECK(mentions(status, "PongSettings.beginner_height_m"));
	config = RenderConfig{};
	config.pong.ball_stiffness_n_per_m = 3000.0;
	config.pong.ball_mass_kg = 0.01;
	CHECK(mentions(validate_render_config(config), "PongSettings.ball_stiffness_n_per_m"));
	config = RenderConfig{};
	config.pong.beginner_target_half_width_m = 1.0;
	config.pong.court_half_width_m = 0.8;
	CHECK(mentions(validate_render_config(config), "PongSettings.beginner_target_half_width_m"));
	HapticsSystem system;
	const RenderConfig before = system.config();
	CHECK_FALSE(reconfigure(system, [](RenderConfig &r_config) { r_config.pong.beginner_height_m = 2.45; }));
	CHECK(std::memcmp(&system.config(), &before, sizeof(RenderConfig)) == 0);
	CHECK(RENDER_MODE_COUNT == 4); // movement, constraint, pong, vehicle.
	CHECK(static_cast<size_t>(RenderMode::PONG) == 2);
}
