#pragma once

// Validation of what the game hands the Pong servo, on the game thread, before it reaches
// the servo (a rejected input or command never does; the previous input stays in force).
// Messages name the field as the binding's dictionaries spell it, e.g.
// "pong_input.players[1].normal: zero length, a direction is needed".

#include "core/base/status.h"
#include "renderers/pong/pong_config.h"
#include "renderers/pong/pong_input.h"

namespace haptics {

// Finite world vectors within MAX_WORLD_M of the origin, speeds within MAX_SPEED, non-zero
// normals, local_player -1 or a seat 0..PONG_MAX_PLAYERS - 1 (seats beyond the configured
// count are ignored by the servo).
Status validate_pong_input(const PongInput &p_input);
// SET_BALL and CORRECT_BALL inside the court of p_config; EFFECT: a player of its count, a kind, a
// direction for RECOIL and HIT, a magnitude and duration when given, an owner (another
// player) for REMOTE.
Status validate_pong_command(const PongCommand &p_command, const PongConfig &p_config);
// What the field table's per-field ranges cannot say: the beginner plane inside the court,
// the beginner target on the back wall, and a contact spring the slowest servo can resolve.
Status validate_pong_config(const PongConfig &p_config);

} // namespace haptics
