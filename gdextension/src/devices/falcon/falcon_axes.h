#pragma once

// Falcon kinematic frame <-> device space (device.h: x right, y up, z toward the user,
// metres, centred on the workspace).
//
// The kinematic frame (falcon_kinematics.h) has z along the grip axis, growing as the grip
// is pulled out toward the user (NIF's cube test: "move the end effector all the way out"
// until z > 0.170; its cube spans z 0.095..0.155), so its z already points toward the user.
// We take its x as the user's right and y as up (a right-handed frame with that z), which is
// how libnifalcon's examples use it (cube walls on x and y, no axis swaps). So the mapping
// is a pure translation by the workspace centre (0, 0, 0.125), and directions (forces,
// velocities) map unchanged:
//
//   device = kinematic - (0, 0, 0.125),   direction_kinematic = direction_device.
//
// Which physical way +x points on a real Falcon is the one thing only hardware can confirm
// (docs/devices/sources.md lists physical directions as a per-device check): if the grip pushed right
// reads -x, negate x AND the force's x here, nowhere else.

#include "core/base/vec3.h"
#include "devices/falcon/falcon_kinematics.h"

namespace haptics::falcon {

constexpr Vec3 falcon_to_device_position(const Vec3 &p_kinematic) {
	return p_kinematic - FALCON_KINEMATIC_CENTRE;
}

constexpr Vec3 device_to_falcon_position(const Vec3 &p_device) {
	return p_device + FALCON_KINEMATIC_CENTRE;
}

constexpr Vec3 device_to_falcon_direction(const Vec3 &p_device) {
	return p_device;
}

constexpr Vec3 falcon_to_device_direction(const Vec3 &p_kinematic) {
	return p_kinematic;
}

} // namespace haptics::falcon
