// Each renderer's own values through its port, as the binding hands them over (bytes of the
// renderer's schema, told apart by layout id): what a port takes reaches the servo, what it
// gives decodes, and anything else is refused by name without changing anything.

#include "renderers/constraint/constraint_port.h"
#include "renderers/pong/pong_port.h"
#include "system/haptics_system.h"
#include "system_config.h"

#include <doctest/doctest.h>

#include <cstring>
#include <vector>

using namespace haptics;

namespace {

bool mentions(const Status &p_status, const char *p_text) {
	return std::strstr(p_status.message(), p_text) != nullptr;
}

template <typename T>
T given(RendererPort &r_port) {
	std::vector<uint8_t> bytes;
	REQUIRE(r_port.give(T::SCHEMA_ID, bytes));
	T value;
	REQUIRE(decode(std::span<const uint8_t>(bytes.data(), bytes.size()), value));
	return value;
}

Status sent(RendererPort &r_port, const auto &p_value) {
	const std::vector<uint8_t> bytes = encode(p_value);
	return r_port.receive(std::span<const uint8_t>(bytes.data(), bytes.size()));
}

} // namespace

TEST_CASE("renderer ports: Pong takes its input and commands and gives its state and events") {
	HapticsSystem system;
	REQUIRE(system.open_simulated_device());
	REQUIRE(reconfigure(system, [](RenderConfig &r_config) { r_config.servo.render_mode = RenderMode::PONG; }));
	RendererPort &port = *system.renderers().all_ports[RenderMode::PONG];

	PongInput input;
	input.local_player = -1;
	for (PongPlayerInput &player : input.players) {
		player.active = false; // Out of play: nothing but the court in the ball's way.
	}
	REQUIRE(sent(port, input));
	PongCommand serve;
	serve.type = PongCommandType::SET_BALL;
	serve.position = { 0.0, 1.0, 0.0 };
	serve.velocity = { 0.0, -3.0, 0.0 };
	REQUIRE(sent(port, serve));
	for (int k = 0; k < 600; ++k) {
		REQUIRE(system.step(0.001));
	}
	const PongState state = given<PongState>(port);
	CHECK(state.player_count == PONG_DEFAULT_PLAYERS);
	CHECK(state.bounces >= 1); // It fell a metre onto the floor and bounced.
	// A zero paddle normal is the seat's own facing.
	CHECK(state.paddle_normals[1] == seat_facing(1));
	const PongEventBatch events = given<PongEventBatch>(port);
	REQUIRE_FALSE(events.events.empty());
	CHECK(events.events[0].type == PongEventType::FLOOR);
	CHECK(given<PongEventBatch>(port).events.empty()); // Drained.
}

TEST_CASE("renderer ports: a value a renderer does not take or give is refused by name") {
	HapticsSystem system;
	RendererPort &pong = *system.renderers().all_ports[RenderMode::PONG];
	const Status status = sent(pong, ProxyState{});
	CHECK(status.code() == StatusCode::INVALID_ARGUMENT);
	CHECK(mentions(status, "none of the values this renderer takes (PongInput, PongCommand, PongWitnessCheck, PongWitnessPose)"));
	std::vector<uint8_t> bytes;
	CHECK(mentions(pong.give(ProxyState::SCHEMA_ID, bytes), "gives PongState, PongEventBatch and PongWitnessVerdict"));
	CHECK(bytes.empty());
	RendererPort &movement = *system.renderers().all_ports[RenderMode::MOVEMENT];
	CHECK(mentions(sent(movement, PongInput{}), "takes no messages of its own"));
	CHECK(mentions(movement.give(PongState::SCHEMA_ID, bytes), "gives no values of its own"));
	// A message that is its layout but not valid: refused by field, nothing queued.
	PongCommand far;
	far.type = PongCommandType::SET_BALL;
	far.position = { 0.0, 1.0, 40.0 };
	CHECK(mentions(sent(pong, far), "outside the court"));
	const uint8_t short_message[] = { 1, 2 };
	CHECK_FALSE(pong.receive(short_message));
}

TEST_CASE("renderer ports: the constraint renderer takes a maze's walls and gives its proxy") {
	HapticsSystem system;
	REQUIRE(system.open_simulated_device());
	REQUIRE(reconfigure(system, [](RenderConfig &r_config) { r_config.servo.render_mode = RenderMode::CONSTRAINT; }));
	RendererPort &port = *system.renderers().all_ports[RenderMode::CONSTRAINT];
	MazeWalls walls;
	walls.mapping.maze_max = { 100.0, 100.0 };
	walls.points = { { 80.0, 0.0 }, { 80.0, 100.0 }, { 0.0, 10.0 } };
	CHECK(mentions(sent(port, walls), "3 points; walls are point pairs"));
	walls.points.pop_back();
	REQUIRE(sent(port, walls));
	Frame heartbeat;
	for (int k = 0; k < 20; ++k) {
		REQUIRE(system.submit_frame(heartbeat));
		REQUIRE(system.step(0.001));
	}
	const ProxyState proxy = given<ProxyState>(port);
	CHECK(proxy.geometry_segments == 1);
	CHECK(proxy.geometry_generation >= 1);
	CHECK(proxy.placed);
}
