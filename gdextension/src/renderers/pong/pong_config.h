#pragma once

// Haptic Battle Pong's constants (PongConfig: the court, the ball, the paddle contact law, spin,
// air friction and the mine and bullet effects) are defined in pong.schema.toml, each field
// with its range, unit and why it has its default. World space is Godot's 3D world: metres,
// y up, the court floor at y = 0 (court.h).

#include "renderers/pong/pong_settings.gen.h"
