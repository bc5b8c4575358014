#pragma once

// From the force the servo renders (device space: x right, y up, newtons) to the one
// constant-force effect a PID stick plays: a polar direction and a signed level, in the
// Linux input units the protocol encodes (direction u16 0..0xFFFF = 0..360°, level s16).
//
// The firmwares turn the direction θ into per-axis factors X = sin θ, Y = -cos θ (AJ and OFB,
// docs/devices/hid-pid.md, "Direction"), on the stick's own HID axes: X grows to the right, Y toward the user (the
// stick pulled back), so "up" in device space is -Y. With
//   hid_x = F.x, hid_y = -F.y     (then the per-device invert flags)
//   θ = atan2(hid_x, -hid_y)      i.e. measured clockwise from "up" (pushing the stick away)
// a force up is θ = 0, right θ = 90° (Linux 0x4000), down 180°, left 270° (0xC000). The
// physical sign of a firmware's axes needs one check per device family (docs/devices/sources.md): the
// invert flags are for that.
//
// Level: |F| / max_force_n at full scale (0x7FFF = the descriptor's magnitude maximum); the
// force is clamped to max_force_n and a non-finite force is zero. Two choices keep the
// traffic down (a changed direction costs an 18-byte Set Effect report, a changed level a
// 4-byte Set Constant Force report):
//  - a direction more than 90° from the previous one is sent as the opposite direction with
//    a negative level, so a force swinging along one line (a wall, a spring about the
//    centre) changes only the level;
//  - a force that quantises to level 0 keeps the previous direction.
// A wheel (one axis) renders only the x component: direction fixed at 90° (+X), signed level.

#include "core/base/vec3.h"

#include <cstdint>

namespace haptics::pid {

struct PidForceMapping {
	double max_force_n = 4.0; // The force at full PID magnitude.
	bool wheel = false; // One axis: x only.
	bool invert_x = false;
	bool invert_y = false;
};

struct PidForce {
	uint16_t direction = 0; // Linux units: 0x4000 = 90°.
	int16_t level = 0; // -0x7FFF..0x7FFF.
};

inline constexpr uint16_t PID_DIRECTION_PLUS_X = 0x4000;

PidForce map_force(const Vec3 &p_force_n, const PidForceMapping &p_mapping, uint16_t p_previous_direction);

// The inverse, for tests and the HUD: the device-space force (z = 0) a direction and level
// ask a firmware with the X = sin θ, Y = -cos θ convention to push.
Vec3 force_from_pid(const PidForce &p_force, const PidForceMapping &p_mapping);

} // namespace haptics::pid
