#pragma once

// What the Pong servo hands the game (servo -> game):
//   PongState  a snapshot after every tick, through a seqlock;
//   PongEvent  bounces, paddle contacts and territory changes, through an SPSC queue the
//              game drains every frame (a full queue drops the event and counts it).
// World space, except the hand forces (the device player's device space, N).

#include "core/base/vec3.h"
#include "renderers/pong/ball.h"
#include "renderers/pong/court.h"
#include "renderers/pong/pong_input.h"

#include <cstddef>
#include <cstdint>
#include <type_traits>

namespace haptics {

enum class PongEventType : int32_t {
	FLOOR = 0, // A floor bounce at >= min_bounce_speed_m_per_s (slower is rolling).
	WALL = 1, // A wall or ceiling bounce.
	PADDLE = 2, // A paddle starts touching the ball.
	RELEASE = 3, // ...and stops.
	TERRITORY = 4, // The ball entered another player's territory (networking hands the
	// simulation over on this).
};
inline constexpr const char *PONG_EVENT_NAMES[] = { "floor", "wall", "paddle", "release", "territory" };

struct PongEvent {
	PongEventType type = PongEventType::FLOOR;
	double time_s = 0.0; // Pong time (servo time while the Pong renderer runs).
	Vec3 position; // The ball centre.
	// FLOOR, WALL: the normal speed into the surface. PADDLE: the closing speed along the
	// paddle normal. RELEASE: the ball's speed as it leaves. TERRITORY: the ball's speed.
	double speed = 0.0;
	int32_t territory = 0; // Of the position (TERRITORY: the new one).
	int32_t player = -1; // PADDLE, RELEASE; -1 otherwise.
	CourtSurface wall = CourtSurface::FLOOR; // WALL only (never FLOOR there).
	// WALL: the player whose back wall (goal) it is, -1 for a side wall or the ceiling.
	int32_t back_wall_of = -1;
};

struct PongPaddleState {
	Vec3 center; // World, m.
	Vec3 normal; // World, unit.
	Vec3 velocity; // World, m/s.
	bool in_contact = false;
};

// The device player's hand force: the renderer's components after the force scale, and
// what was written to the device (with impacts and the safety stage). Device space, N.
struct PongHandForce {
	Vec3 contact; // The paddle's contact law.
	Vec3 spin; // The spinning ball's drag on the paddle.
	Vec3 effects; // Recoil, hit, slow, heavy, remote.
	Vec3 total; // Written to the device.
};

// One per kind at most (a new effect of a kind replaces the running one).
inline constexpr size_t PONG_MAX_ACTIVE_EFFECTS = PONG_EFFECT_KIND_COUNT - 1;

struct PongEffectState {
	PongEffectKind kind = PongEffectKind::NONE;
	double remaining_s = 0.0;
};

struct PongState {
	double time_s = 0.0;
	BallState ball;
	// What a running CORRECT_BALL still has to blend in, m: the corrected ball, the one a
	// master streams and the territory is taken from, is at ball.position + this.
	Vec3 ball_correction;
	// The most a correction moved the ball in one tick this session, m (issue 24's bound: 0.05).
	double correction_step_max_m = 0.0;
	int32_t territory = 0;
	int32_t player_count = PONG_DEFAULT_PLAYERS; // The first player_count entries of players.
	PongPaddleState players[PONG_MAX_PLAYERS];
	PongHandForce hand_force;
	PongEffectState effects[PONG_MAX_ACTIVE_EFFECTS]; // The device player's, the first effect_count.
	uint32_t effect_count = 0;
	uint64_t paddle_contacts = 0; // Contacts started this session.
	uint64_t bounces = 0; // FLOOR and WALL events this session.
	uint64_t events_dropped = 0; // Events the game did not drain in time.
	// The remote-operation coupling's net work on the device player's hand since the effects
	// were last cleared, J (HandEffects::remote_work_j: before the force scale).
	double remote_work_j = 0.0;
};

static_assert(std::is_trivially_copyable_v<PongEvent>);
static_assert(std::is_trivially_copyable_v<PongState>);

} // namespace haptics
