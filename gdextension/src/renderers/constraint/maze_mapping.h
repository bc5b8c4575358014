#pragma once

// Position control for the constraint-based condition: the device's workspace maps onto the
// whole maze, so every point of the maze is reachable without clutching.
//
//   maze space:    the level's own 2D units (e.g. Godot pixels), a rectangle [min, max];
//                  y grows DOWN when maze_y_down (Godot 2D), up otherwise.
//   device space:  coordinates.h, x right, y up, metres; only x and y are used (the maze
//                  lies in the device's x-y plane; z, toward the user, is left free).
//
// The map is affine with ONE scale for both axes: a non-uniform scale would turn the round
// proxy into an ellipse in the hand and make walls feel stiffer in one direction than in
// the other. The scale is chosen so the maze rectangle fits the workspace shape:
//   DISC:   the rectangle's corners lie on the circle of radius R (its diagonal spans 2R):
//           every maze point is inside a spherical workspace.
//   SQUARE: the rectangle's longer side spans 2R (a square of half-side R): more travel per
//           maze unit, but the maze corners lie outside a spherical workspace's equator.
// R is workspace_half_extent_m, or the device's workspace radius when that is 0.

#include "core/base/status.h"
#include "core/base/vec2.h"
#include "renderers/constraint/constraint.gen.h"

#include <cstdint>
#include <type_traits>

namespace haptics {

// WorkspaceShape and MazeMapping: constraint.schema.toml.

// The resolved map (the device's radius filled in). Maze -> device:
//   d = centre_m + metres_per_unit * (m.x - maze_centre.x, y_sign * (m.y - maze_centre.y))
struct MazeTransform {
	Vec2 maze_centre;
	Vec2 device_centre_m;
	double metres_per_unit = 1.0;
	double y_sign = -1.0; // -1 when the maze's y grows down.

	Vec2 to_device(const Vec2 &p_maze) const {
		return { device_centre_m.x + metres_per_unit * (p_maze.x - maze_centre.x),
			device_centre_m.y + metres_per_unit * y_sign * (p_maze.y - maze_centre.y) };
	}
	Vec2 to_maze(const Vec2 &p_device_m) const {
		const double units_per_metre = 1.0 / metres_per_unit;
		return { maze_centre.x + units_per_metre * (p_device_m.x - device_centre_m.x),
			maze_centre.y + units_per_metre * y_sign * (p_device_m.y - device_centre_m.y) };
	}
};

// The mapping must be valid (validate_maze_mapping); p_device_radius_m > 0 is used when
// workspace_half_extent_m is 0.
MazeTransform resolve_maze_mapping(const MazeMapping &p_mapping, double p_device_radius_m);

// Messages name the field, e.g. "mapping.maze_max.x must be > mapping.maze_min.x (got 0 <= 5)".
Status validate_maze_mapping(const MazeMapping &p_mapping);

} // namespace haptics
