#pragma once

// The one mapping between game space and device space. Everything in the core is in device
// space; the binding converts at the boundary with these functions and nothing else.
//
//   game space (Godot 2D):  x right, y DOWN, pixels.
//   device space:           x right, y UP, z toward the user, metres / newtons / m/s.
//
// A game vector (gx, gy) maps to device (gx, -gy, 0) (times a scale for lengths and
// velocities); device (dx, dy, dz) maps back to game (dx, -dy) and the depth axis z, which
// the 2D game has no use for, is dropped. "Down" is therefore DEVICE_DOWN = (0, -1, 0)
// everywhere in the core (weight, water inertia).

#include "core/base/vec3.h"

#include <cstdint>

namespace haptics {

inline constexpr Vec3 DEVICE_DOWN{ 0.0, -1.0, 0.0 };

// The game a value came from. A 2D game's vectors are (x right, y down) and lose depth; a 3D
// game's are in Godot's 3D view axes (x right, y up, z toward the viewer), which are device
// axes as they are. A value's 3D form (its schema's gd3) says SPACE.
enum class GameSpace : uint8_t {
	PLANE,
	SPACE,
};

// Direction-like game vectors (contact normals, impact directions): no scale, since the
// force model normalises them anyway.
constexpr Vec3 game_to_device_direction(double p_game_x, double p_game_y) {
	return { p_game_x, -p_game_y, 0.0 };
}

// Length-like game vectors: p_pixels_per_metre is the game's world scale (e.g. 100 px = 1 m),
// so a velocity in px/s becomes m/s.
constexpr Vec3 game_to_device_scaled(double p_game_x, double p_game_y, double p_pixels_per_metre) {
	return { p_game_x / p_pixels_per_metre, -p_game_y / p_pixels_per_metre, 0.0 };
}

// A 2-axis stick in a 3D game works the ground plane: pushed forward (device +y) it points
// into the screen (-z), and of a 3D force it renders the ground plane's part.
constexpr Vec3 stick_to_ground(const Vec3 &p_stick) {
	return { p_stick.x, 0.0, -p_stick.y };
}
constexpr Vec3 ground_to_stick(const Vec3 &p_space) {
	return { p_space.x, -p_space.z, 0.0 };
}

struct GameVec2 {
	double x = 0.0;
	double y = 0.0;
};

// E.g. the input vector as the game's movement intent: pushing the stylus up gives a game
// vector pointing up the screen (negative y).
constexpr GameVec2 device_to_game(const Vec3 &p_device) {
	return { p_device.x, -p_device.y };
}

} // namespace haptics
