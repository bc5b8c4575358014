#pragma once

// The court and the two sides, defined once.
//
// World: Godot 3D, metres, y up. The floor is y = 0; the court spans x in [-W, W] and
// z in [-L, L] (W = court_half_width_m, L = court_half_length_m), with walls on all four
// sides and a ceiling at wall_height_m. No net: the plane z = 0 divides the territories.
// Player 0 ("near") owns z >= 0, player 1 ("far") z < 0.
//
// Device space (core/coordinates.h): x right, y up, z toward the user. Player 0 sits at
// +z looking toward -z, so its device frame is the world's axes. Player 1 sits at -z facing
// the other way: its device frame is the world turned 180 degrees about y (device x ->
// world -x, device z -> world -z). That rotation is its own inverse, so side_rotation()
// maps device -> world and world -> device alike.

#include "core/vec3.h"
#include "pong/pong_config.h"

#include <cstdint>

namespace haptics {

inline constexpr int PONG_PLAYERS = 2;

// Which court surface; also the order of the names the binding uses.
enum class CourtSurface : int32_t {
	LEFT = 0, // x = -W
	RIGHT = 1, // x = +W
	BACK_NEAR = 2, // z = +L, behind player 0
	BACK_FAR = 3, // z = -L, behind player 1
	CEILING = 4, // y = wall height
	FLOOR = 5, // y = 0
};
inline constexpr int COURT_SURFACE_COUNT = 6;
// The walls' names in enum order (the floor has its own event type).
inline constexpr const char *COURT_WALL_NAMES[] = { "left", "right", "back_near", "back_far", "ceiling" };

struct CourtPlane {
	CourtSurface surface;
	Vec3 normal; // Unit, pointing into the court.
	double offset; // The plane is dot(normal, p) = offset.
};

// The six planes of the court of p_config, each facing inward.
void court_planes(const PongConfig &p_config, CourtPlane (&r_planes)[COURT_SURFACE_COUNT]);

// 0 for z >= 0 (player 0), 1 otherwise.
constexpr int territory_of(const Vec3 &p_world) {
	return p_world.z >= 0.0 ? 0 : 1;
}

// Player p_player's device frame <-> world (both directions: the rotation is an involution).
constexpr Vec3 side_rotation(int p_player, const Vec3 &p_v) {
	return p_player == 1 ? Vec3{ -p_v.x, p_v.y, -p_v.z } : p_v;
}

// The paper's mirror about the plane dividing the left and right halves of the workspace.
constexpr Vec3 mirror_left_right(const Vec3 &p_device) {
	return { -p_device.x, p_device.y, p_device.z };
}

} // namespace haptics
