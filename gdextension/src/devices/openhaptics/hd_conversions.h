#pragma once

// Pure conversions between HDAPI's arrays and our device space, kept apart from the device
// so that each is tested on its own (and cheap enough for the scheduler callback: no
// allocation, no branches on the hot path beyond finiteness and plausibility).
//
// Units (docs/devices/openhaptics.md, "Units and layouts"): positions mm, velocities mm/s, the workspace box mm
// (minX, minY, minZ, maxX, maxY, maxZ), forces N, stiffness N/mm. Ours: m, m/s, N, N/m.
//
// Axes: HD's device frame is x right, y up, z toward the user, the same as ours
// (device.h), so the mapping is the identity. Evidence: docs/devices/openhaptics.md, "Units
// and layouts" (ROS omni_state maps
// device (x, y, z) to ROS (x, -z, y), i.e. device +y is up, and sends ROS forces back as
// (Fx, Fz, -Fy), the inverse of the same map); public Touch drivers annotate
// HD_CURRENT_POSITION with "+Y up, +X right"; HD's frame is right-handed (its transforms
// are rotations), which puts +z toward the user. Only a real Touch can confirm the signs by
// feel: push the stylus right/up/toward you and watch the position's x/y/z grow.

#include "core/base/status.h"
#include "core/base/vec3.h"
#include "core/device/device.h"

namespace haptics::openhaptics {

inline constexpr double MM_TO_M = 1e-3;
inline constexpr double N_PER_MM_TO_N_PER_M = 1e3;

// The farthest a position may lie from the workspace centre before it is a corrupt reading,
// not a stylus. Touch/Omni workspaces are about 0.16 m across, the desktop Phantoms' about
// 0.4 m and the largest Phantom Premium's under 1 m, so no real stylus gets near 10 m; yet
// the bound catches the garbage a broken runtime or a bad frame writes (1e300, stale
// memory) before it becomes a position the game acts on. A bound near the workspace would
// turn a device we do not know, or a slightly off calibration, into a failure.
inline constexpr double MAX_PLAUSIBLE_POSITION_M = 10.0;

struct HdWorkspace {
	Vec3 centre_m; // Centre of the usable box: subtracted so positions are centred.
	Vec3 half_extent_m;
	// Radius of the largest sphere inside the box (its smallest half extent): every point
	// within it is reachable. The Touch's box is shallow, so this is its depth; a game that
	// plays in x/y can widen its input range with force_model.input_radius_m.
	double radius_m = 0.0;
};

// From HD_USABLE_WORKSPACE_DIMENSIONS (mm). Errors name the parameter and the bad value:
// not finite, or min >= max on an axis.
Status workspace_from_hd_box(const double p_box_mm[6], HdWorkspace &r_workspace);

// HD_CURRENT_POSITION (mm) -> metres, centred on the workspace.
Vec3 position_from_hd(const double p_position_mm[3], const Vec3 &p_centre_m);
// Whether a position from position_from_hd() can be a real one: finite and no farther than
// MAX_PLAUSIBLE_POSITION_M from the workspace centre.
bool position_plausible(const Vec3 &p_position_m);
// HD_CURRENT_VELOCITY (mm/s) -> m/s.
Vec3 velocity_from_hd(const double p_velocity_mm_s[3]);
// HD_CURRENT_TRANSFORM (4x4, column-major: rotation columns at [0..2], [4..6], [8..10],
// translation at [12..14]) -> the rotation as a unit quaternion. A matrix that is not finite
// or holds no rotation (a column far from unit length, e.g. all zero) gives identity.
Orientation orientation_from_hd_transform(const double p_transform[16]);

// The force we may set this tick: finite, the continuous share (force_n - impact_n) capped
// at p_continuous_limit_n (<= 0: no cap), the total capped at p_peak_limit_n. A command
// that is not finite gives zero. The servo's safety stage has already done the same; this is
// the last guard before the motors (docs/devices/openhaptics.md).
Vec3 bounded_force(const ForceCommand &p_command, double p_continuous_limit_n, double p_peak_limit_n);

} // namespace haptics::openhaptics
