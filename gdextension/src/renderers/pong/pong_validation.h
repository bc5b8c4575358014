#pragma once

// Validation of what the game hands the Pong servo, on the game thread, before it reaches
// the servo (a rejected input or command never does; the previous input stays in force):
// the limits of pong.schema.toml, then what they cannot say. Messages name the field as
// GDScript spells it, e.g. "PongInput.players[1].avatar: length 2000 is above 1000".

#include "core/base/status.h"
#include "renderers/pong/pong_config.h"
#include "renderers/pong/pong_input.h"

namespace haptics {

// The schema's limits (seats beyond the configured count are ignored by the servo).
Status validate_pong_input(const PongInput &p_input);
// SET_BALL and CORRECT_BALL inside the court of p_config; EFFECT: a player of its count, a
// direction for RECOIL and HIT, a duration above zero when given, an owner (another player)
// for REMOTE.
Status validate_pong_command(const PongCommand &p_command, const PongConfig &p_config);
// What the field table's per-field ranges cannot say: the beginner plane inside the court,
// the beginner target on the back wall, and a contact spring the slowest servo can resolve.
Status validate_pong_config(const PongConfig &p_config);

} // namespace haptics
