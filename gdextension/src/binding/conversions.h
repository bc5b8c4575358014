// Engine values <-> the core's plain structs. GDScript speaks game axes (x right, y down) in
// SI units (the probe has already turned pixels into metres); the core speaks device axes
// (y up). The flip happens here and only here, through core/base/coordinates.h. The dictionary
// layouts are documented for GDScript authors in doc_classes/HapticsServer.xml; keys end in
// their unit, and the names used before 0.3.0 are still read, with a deprecation warning.
#pragma once

#include <string>

#include <vector>

#include <span>

#include "binding/containers.h"
#include "core/device/device.h"
#include "core/render/force_components.h"
#include "core/render/frame.h"
#include "core/servo/servo_stats.h"
#include "renderers/constraint/constraint_channels.h"
#include "renderers/constraint/maze_mapping.h"
#include "renderers/constraint/swept_disc.h"

namespace haptics::binding {

bool frame_from_dictionary(const gd::Dictionary &p_dictionary, Frame &r_frame, std::string &r_error);
bool impact_from_dictionary(const gd::Dictionary &p_dictionary, ImpactEvent &r_event,
		std::string &r_error);

// Walls as consecutive point pairs (a0, b0, a1, b1, ...) in maze units (the level's pixels).
bool segments_from_points(const gd::PackedVector2Array &p_points, std::vector<Segment2> &r_segments,
		std::string &r_error);
// { maze_min: Vector2, maze_max: Vector2, workspace: WORKSPACE_DISC | WORKSPACE_SQUARE (or
//   "disc" | "square"), half_extent_m: float, centre_m: Vector2 }; maze_min and maze_max are
//   required.
bool mapping_from_dictionary(const gd::Dictionary &p_dictionary, MazeMapping &r_mapping,
		std::string &r_error);
gd::Dictionary proxy_state_to_dictionary(const ProxyState &p_state);

gd::Vector2 to_game(const Vec3 &p_device);
// The parts by the active renderer's names (p_names), then continuous, smoothed, impact, total.
gd::Dictionary forces_to_dictionary(const ForceComponents &p_forces, std::span<const char *const> p_names);
gd::Dictionary stats_to_dictionary(const ServoStats &p_stats);
gd::Dictionary limits_to_dictionary(const DeviceLimits &p_limits);
// Limits plus input_dof, output_dof, output ("directional", "vibration", "none"),
// native_rate_hz, has_orientation, needs_homing, physical, button_count.
gd::Dictionary capabilities_to_dictionary(const DeviceCapabilities &p_capabilities);
// {io: "ok" | "disconnected" | "failed", reason: String}.
gd::Dictionary device_status_to_dictionary(const DeviceStatus &p_status);

} // namespace haptics::binding
