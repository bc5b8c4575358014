// Engine values <-> the core's plain structs. GDScript speaks game axes (x right, y down) in
// SI units (the probe has already turned pixels into metres); the core speaks device axes
// (y up). The flip happens here and only here, through core/coordinates.h.
//
// Frame dictionary (every key optional; unknown keys are errors):
//   contacts: Array of { normal: Vector2, stiffness: float, damping: float }
//             (a contact without stiffness/damping uses the default contact material)
//   resting:  Array of { normal: Vector2, mass: float (kg) }
//   water:    { inside: bool, drag: float (N·s/m), inertia: float (N, along down) }
//   velocity: Vector2, the player's velocity in m/s
//   sequence: int, time: float (informational)
// Impact dictionary: { direction: Vector2, speed: float (m/s), and optionally gain (N·s/m),
//   frequency (Hz), decay (s) — all three or none, none meaning the default material }.
#pragma once

#include <string>

#include <vector>

#include "core/config.h"
#include "core/constraint_geometry.h"
#include "core/maze_mapping.h"
#include "core/frame.h"
#include "core/servo_pipeline.h"
#include "core/servo_stats.h"
#include "devices/device.h"
#include "godot/containers.h"

namespace haptics::godot {

bool frame_from_dictionary(const gd::Dictionary &p_dictionary, Frame &r_frame, std::string &r_error);
bool impact_from_dictionary(const gd::Dictionary &p_dictionary, ImpactEvent &r_event,
		std::string &r_error);

// Applies the keys present in p_values to r_config's section p_section ("force_model",
// "smoothing", "safety" or "telemetry"); r_config is only meaningful when true is returned.
bool apply_config_section(const std::string &p_section, const gd::Dictionary &p_values,
		RenderConfig &r_config, std::string &r_error);
gd::Dictionary config_to_dictionary(const RenderConfig &p_config);

// Walls as consecutive point pairs (a0, b0, a1, b1, ...) in maze units (the level's pixels).
bool segments_from_points(const gd::PackedVector2Array &p_points, std::vector<Segment2> &r_segments,
		std::string &r_error);
// { maze_min: Vector2, maze_max: Vector2, workspace: "disc"|"square", half_extent: float m,
//   centre: Vector2 m }; maze_min and maze_max are required.
bool mapping_from_dictionary(const gd::Dictionary &p_dictionary, MazeMapping &r_mapping,
		std::string &r_error);
gd::Dictionary proxy_state_to_dictionary(const ServoOutput &p_output);

gd::Vector2 to_game(const Vec3 &p_device);
gd::Dictionary forces_to_dictionary(const ForceComponents &p_forces);
gd::Dictionary stats_to_dictionary(const ServoStats &p_stats);
gd::Dictionary limits_to_dictionary(const DeviceLimits &p_limits);

} // namespace haptics::godot
