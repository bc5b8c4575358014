// Haptic Battle Pong's dictionaries <-> the core's plain structs (renderers/pong/pong_input.h,
// renderers/pong/pong_output.h). World vectors are Godot's 3D world, which is the core's world too:
// they pass straight through (Vector3, metres). Only the hand forces are in device space.
// Unknown keys are errors, missing keys keep the defaults; errors name the key
// ("pong_input.players[1].normal: expected a Vector3, got Vector2"). The layouts are
// documented for GDScript authors in doc_classes/HapticsServer.xml.
#pragma once

#include <string>

#include "binding/containers.h"
#include "renderers/pong/pong_input.h"
#include "renderers/pong/pong_output.h"

namespace haptics::binding {

// {beginner: bool, local_player: int (-1, 0, 1), players: [2 x {avatar: Vector3,
//  kinematic: bool, paddle_offset: Vector3, paddle_velocity: Vector3, normal: Vector3,
//  spin: bool, gun: bool, active: bool}]}
bool pong_input_from_dictionary(const gd::Dictionary &p_dictionary, PongInput &r_input, std::string &r_error);
// {type: "set_ball" | "correct_ball", position: Vector3 (required), velocity: Vector3, spin: Vector3}
// {type: "effect", player: int, kind: "recoil" | "hit" | "slow" | "heavy" | "remote" | "none",
//  direction: Vector3 (recoil, hit), magnitude_n: float, duration_s: float, owner: int}
// {type: "clear_effects"}
bool pong_command_from_dictionary(const gd::Dictionary &p_dictionary, PongCommand &r_command, std::string &r_error);
gd::Dictionary pong_state_to_dictionary(const PongState &p_state);
gd::Dictionary pong_event_to_dictionary(const PongEvent &p_event);

} // namespace haptics::binding
