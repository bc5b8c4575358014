#pragma once

// What the game hands the Pong servo (game -> servo), in world space unless named
// (pong_messages.schema.toml defines the values):
//   PongInput    the latest paddles and modes, every frame, through a seqlock;
//   PongCommand  one-off orders (serve or correct the ball, start or clear an effect),
//                through an SPSC queue.
// Both are validated on the game thread (pong_validation.h) before they reach the servo.

#include "core/base/vec3.h"
#include "renderers/pong/court.h"
#include "renderers/pong/pong_messages.gen.h"

#include <cstdint>
#include <type_traits>

namespace haptics {

// The servo moves a game-driven (kinematic) paddle on by its velocity for at most this long
// after the input arrived: a frame or three at 60 Hz, never far if the game stalls.
inline constexpr double PONG_MAX_EXTRAPOLATION_S = 0.05;
// A game-driven paddle whose pose is pose_age_s old (a remote player's, over the network) is
// also carried on over that age, at most this long: a stalled stream holds the paddle.
inline constexpr double PONG_MAX_POSE_EXTRAPOLATION_S = 0.15;

// The paddle's face in its player's device frame: away from the user, toward the
// opponent. Also where a device orientation's identity points the paddle.
inline constexpr Vec3 PADDLE_FACING_DEVICE{ 0.0, 0.0, -1.0 };

// Player p_player's paddle facing the opponent: what a zero PongPlayerInput::normal means.
constexpr Vec3 seat_facing(int p_player) {
	return side_rotation(p_player, PADDLE_FACING_DEVICE);
}

// The input before the game sends any: every seat in play, its paddle facing the opponent.
constexpr PongInput default_pong_input() {
	PongInput input;
	for (int p = 0; p < PONG_MAX_PLAYERS; ++p) {
		input.players[p].normal = seat_facing(p);
	}
	return input;
}

// PongEffectKind values by count (EnumInfo), for arrays indexed by kind.
inline constexpr int PONG_EFFECT_KIND_COUNT = static_cast<int>(EnumInfo<PongEffectKind>::COUNT);

} // namespace haptics
