#pragma once

// The court and the two sides, defined once.
//
// World: Godot 3D, metres, y up. The floor is y = 0; walls on all four sides and a ceiling
// at wall_height_m. No net: the territories meet along lines through the centre.
//
// Two players (PongConfig::players = 2): x in [-W, W], z in [-L, L] (W = court_half_width_m,
// L = court_half_length_m). Player 0 ("near") owns z >= 0, player 1 ("far") z < 0; their
// back walls are z = +L and z = -L.
//
// Four players (the paper's future work, issue 11): a square court, x and z both in
// [-L, L]. Each territory is a triangle of area L^2, the 2-player half's 2 W L at the
// default W = L / 2, so a player defends as much floor in either layout. Each side is one player's back wall (its goal) and each player owns the
// region nearer its back wall than any other, split by the diagonals. Players 0 (+z) and
// 1 (-z) keep their 2-player meaning so a 2-player game is a 4-player game with two
// seats; 2 takes +x and 3 takes -x (opposite pairs stay 0/1 and 2/3, so "the opponent
// across" is p ^ 1 in both layouts). On a diagonal the z players win the tie (|z| >= |x|),
// as z = 0 goes to player 0 in the 2-player court: every point has exactly one owner.
//
// Device space (core/base/coordinates.h): x right, y up, z toward the user. Each player sits
// behind its back wall looking at the centre, so its device frame is the world turned
// about y by its seat's angle: 0 for player 0 (the world's axes), 180 degrees for player 1
// (device x -> world -x, z -> -z), +90 for player 2 (device forward -z -> world -x) and -90
// for player 3 (device forward -> world +x). Quarter turns are exact (no trigonometry).

#include "core/base/vec3.h"
#include "renderers/pong/pong.gen.h"
#include "renderers/pong/pong_config.h"

#include <cstdint>

namespace haptics {

// PONG_MAX_PLAYERS (fixed-size arrays in the servo use it: no allocation) and
// PONG_DEFAULT_PLAYERS: pong.schema.toml. Kept for the 2-player callers: the default count.
inline constexpr int PONG_PLAYERS = PONG_DEFAULT_PLAYERS;

// Whether a court of p_count players is built (2 and 4; 3 would need a hexagonal or
// triangular court and is not).
constexpr bool valid_player_count(int p_count) {
	return p_count == 2 || p_count == 4;
}

// CourtSurface (pong.schema.toml): LEFT x = -W, RIGHT x = +W, BACK_NEAR z = +L (behind player
// 0), BACK_FAR z = -L (behind player 1), CEILING at the wall height, FLOOR y = 0; with 4
// players RIGHT is player 2's back wall and LEFT player 3's.
inline constexpr int COURT_SURFACE_COUNT = static_cast<int>(EnumInfo<CourtSurface>::COUNT);

struct CourtPlane {
	CourtSurface surface;
	Vec3 normal; // Unit, pointing into the court.
	double offset; // The plane is dot(normal, p) = offset.
};

// Half the court's extent along x and z for p_config's player count.
constexpr double court_half_x(const PongConfig &p_config) {
	return p_config.players == 4 ? p_config.court_half_length_m : p_config.court_half_width_m;
}
constexpr double court_half_z(const PongConfig &p_config) {
	return p_config.court_half_length_m;
}

// The six planes of the court of p_config, each facing inward.
void court_planes(const PongConfig &p_config, CourtPlane (&r_planes)[COURT_SURFACE_COUNT]);

// The player whose territory holds p_world in a court of p_players (2 or 4).
constexpr int territory_of(const Vec3 &p_world, int p_players = PONG_DEFAULT_PLAYERS) {
	const double ax = p_world.x < 0.0 ? -p_world.x : p_world.x;
	const double az = p_world.z < 0.0 ? -p_world.z : p_world.z;
	if (p_players != 4 || az >= ax) {
		return p_world.z >= 0.0 ? 0 : 1;
	}
	return p_world.x > 0.0 ? 2 : 3;
}

// p_offset without its part across p_surface: what moves a point along that surface.
constexpr Vec3 along_surface(CourtSurface p_surface, const Vec3 &p_offset) {
	switch (p_surface) {
		case CourtSurface::LEFT:
		case CourtSurface::RIGHT:
			return { 0.0, p_offset.y, p_offset.z };
		case CourtSurface::BACK_NEAR:
		case CourtSurface::BACK_FAR:
			return { p_offset.x, p_offset.y, 0.0 };
		default: // The ceiling and the floor.
			return { p_offset.x, 0.0, p_offset.z };
	}
}

// The player whose back wall p_surface is in a court of p_players, or -1 (a side wall with
// 2 players, the ceiling, the floor).
constexpr int back_wall_owner(CourtSurface p_surface, int p_players = PONG_DEFAULT_PLAYERS) {
	switch (p_surface) {
		case CourtSurface::BACK_NEAR:
			return 0;
		case CourtSurface::BACK_FAR:
			return 1;
		case CourtSurface::RIGHT:
			return p_players == 4 ? 2 : -1;
		case CourtSurface::LEFT:
			return p_players == 4 ? 3 : -1;
		default:
			return -1;
	}
}

// Player p_player's seat as quarter turns about +y (counter-clockwise seen from above).
constexpr int side_quarter_turns(int p_player) {
	constexpr int TURNS[PONG_MAX_PLAYERS] = { 0, 2, 1, 3 };
	return p_player >= 0 && p_player < PONG_MAX_PLAYERS ? TURNS[p_player] : 0;
}

// p_v turned about +y by p_turns quarter turns: (x, z) -> (x cos + z sin, -x sin + z cos).
constexpr Vec3 turn_about_y(int p_turns, const Vec3 &p_v) {
	switch (((p_turns % 4) + 4) % 4) {
		case 1:
			return { p_v.z, p_v.y, -p_v.x };
		case 2:
			return { -p_v.x, p_v.y, -p_v.z };
		case 3:
			return { -p_v.z, p_v.y, p_v.x };
		default:
			return p_v;
	}
}

// Player p_player's device frame -> world.
constexpr Vec3 side_rotation(int p_player, const Vec3 &p_v) {
	return turn_about_y(side_quarter_turns(p_player), p_v);
}

// World -> player p_player's device frame (the inverse of side_rotation).
constexpr Vec3 side_rotation_inverse(int p_player, const Vec3 &p_v) {
	return turn_about_y(-side_quarter_turns(p_player), p_v);
}

// The paper's mirror about the plane dividing the left and right halves of the workspace.
constexpr Vec3 mirror_left_right(const Vec3 &p_device) {
	return { -p_device.x, p_device.y, p_device.z };
}

} // namespace haptics
