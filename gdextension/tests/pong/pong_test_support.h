#pragma once

// Small builders shared by the Pong doctests: a game-driven paddle, a ball, the events a
// sim raised, a few steps.

#include "renderers/pong/pong_sim.h"

#include <vector>

namespace haptics::test {

inline constexpr double PONG_DT = 0.001;

// Player p_player's paddle driven by the game: centre p_center (the avatar, no offset),
// facing p_normal, moving at p_velocity.
inline PongPlayerInput game_paddle(const Vec3 &p_center, const Vec3 &p_normal, const Vec3 &p_velocity = {}) {
	PongPlayerInput player;
	player.avatar = p_center;
	player.kinematic = true;
	player.normal = p_normal;
	player.paddle_velocity = p_velocity;
	return player;
}

// Both paddles game-driven and out of the way (behind the back walls' reach, inactive),
// no device player.
inline PongInput idle_input() {
	PongInput input;
	input.local_player = -1;
	for (PongPlayerInput &player : input.players) {
		player.active = false;
	}
	return input;
}

inline PongCommand set_ball(const Vec3 &p_position, const Vec3 &p_velocity = {}, const Vec3 &p_spin = {}) {
	PongCommand command;
	command.type = PongCommandType::SET_BALL;
	command.position = p_position;
	command.velocity = p_velocity;
	command.spin = p_spin;
	return command;
}

inline std::vector<PongEvent> take_events(PongSim &r_sim) {
	std::vector<PongEvent> events;
	PongEvent event;
	while (r_sim.events().pop(event)) {
		events.push_back(event);
	}
	return events;
}

inline size_t count_events(const std::vector<PongEvent> &p_events, PongEventType p_type) {
	size_t count = 0;
	for (const PongEvent &event : p_events) {
		count += event.type == p_type ? 1 : 0;
	}
	return count;
}

} // namespace haptics::test
