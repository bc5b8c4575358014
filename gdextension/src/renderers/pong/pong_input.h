#pragma once

// What the game hands the Pong servo (game -> servo), in world space unless named.
//   PongInput    the latest paddles and modes, every frame, through a seqlock;
//   PongCommand  one-off orders (serve or correct the ball, start or clear an effect),
//                through an SPSC queue.
// Both are validated on the game thread (pong_validation.h) before they reach the servo.

#include "core/base/vec3.h"
#include "renderers/pong/court.h"

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

struct PongPlayerInput {
	Vec3 avatar; // The workspace centre in the world, moved by the game.
	// The paddle's pose comes from the game (computer player, keyboard second player,
	// remote player), not from the device. A player other than PongInput::local_player
	// always is; this flag makes the local player's paddle game-driven too.
	bool kinematic = false;
	Vec3 paddle_offset; // Paddle centre - avatar, game-driven paddles only.
	Vec3 paddle_velocity; // Game-driven paddles only, m/s.
	// Unit (any length is accepted and normalised). Game-driven paddles, and the device
	// paddle when the device reports no orientation.
	Vec3 normal;
	bool spin = false; // Spin mode: brushing the ball spins it.
	bool gun = false; // Held as a gun: it does not touch the ball.
	bool active = true; // In play.
	// How old paddle_offset and paddle_velocity were when this input was handed over, s: 0
	// for a paddle this machine drives, the sample's age for a remote player's (network
	// delay, as the networking measures it). The servo carries the paddle on by its velocity
	// over it (at most PONG_MAX_POSE_EXTRAPOLATION_S), and the remote-operation mine's target
	// is this player's stylus moved on over it (hand_effects.h).
	double pose_age_s = 0.0;
};

// A player's input before the game says otherwise: in play, its paddle facing the opponent.
constexpr PongPlayerInput default_player_input(int p_player) {
	PongPlayerInput input;
	input.normal = side_rotation(p_player, PADDLE_FACING_DEVICE);
	return input;
}

struct PongInput {
	bool beginner = false; // No gravity; the ball stays at beginner_height_m.
	// The player whose paddle the local device moves, or -1 for none (a match of game-driven
	// paddles). Effects act on this player's hand.
	int32_t local_player = 0;
	// The first PongConfig::players entries are used; the rest are ignored.
	PongPlayerInput players[PONG_MAX_PLAYERS] = { default_player_input(0), default_player_input(1),
		default_player_input(2), default_player_input(3) };
};

enum class PongEffectKind : int32_t {
	NONE = 0, // The fourth mine: damage and rumble (push_impact) only, no hand effect.
	RECOIL = 1, // Constant force along a direction for a moment (the gun's recoil).
	HIT = 2, // The same when a bullet hits the player.
	SLOW = 3, // Viscous paddle, F = -b v.
	HEAVY = 4, // A weight on the paddle, F = constant down.
	REMOTE = 5, // A spring to the owner's mirrored stylus.
};
inline constexpr int PONG_EFFECT_KIND_COUNT = 6;
inline constexpr const char *PONG_EFFECT_NAMES[] = { "none", "recoil", "hit", "slow", "heavy", "remote" };

enum class PongCommandType : int32_t {
	SET_BALL = 0, // A serve: the ball is put there at once.
	EFFECT = 1,
	CLEAR_EFFECTS = 2,
	// A network correction: the ball's state as it should be now, blended in without a jump
	// while the ball flies on (ball_correction.h).
	CORRECT_BALL = 3,
};
inline constexpr const char *PONG_COMMAND_NAMES[] = { "set_ball", "effect", "clear_effects", "correct_ball" };

struct PongCommand {
	PongCommandType type = PongCommandType::SET_BALL;
	// SET_BALL, CORRECT_BALL: the ball's whole state, world.
	Vec3 position;
	Vec3 velocity;
	Vec3 spin; // rad/s.
	// EFFECT.
	int32_t player = 0; // Whose hand: only the local device player's is rendered here.
	PongEffectKind kind = PongEffectKind::NONE;
	Vec3 direction; // World, RECOIL and HIT (normalised).
	// RECOIL, HIT, HEAVY: the force. SLOW, REMOTE: a cap on the force. Default: the
	// config's (recoil_force_n, hit_force_n, heavy_force_n, remote_max_force_n; SLOW none).
	double magnitude_n = 0.0;
	bool use_default_magnitude = true;
	// Default: recoil_duration_s, hit_duration_s, mine_effect_duration_s.
	double duration_s = 0.0;
	bool use_default_duration = true;
	int32_t owner = 1; // REMOTE: the player whose stylus pulls (another one).
};

static_assert(std::is_trivially_copyable_v<PongInput>);
static_assert(std::is_trivially_copyable_v<PongCommand>);

} // namespace haptics
