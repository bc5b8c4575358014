#pragma once

// The Falcon's parallel (delta) kinematics, Stamper's model as libnifalcon states it
// (docs/devices/falcon.md, "Kinematics" [NIF FalconGeometry.h, FalconKinematicStamper.cpp]),
// rewritten from the equations:
//
//  - Each leg i sits at angle phi_i around the z axis. In the leg's frame (u, v, w) =
//    (R(phi_i) p) + (-r, -s, 0) its three joint angles satisfy the closure
//        u + c - a cos(t1) = L cos(t2),   w - a sin(t1) = L sin(t2),   v + f = b cos(t3),
//    with L = d + e + b sin(t3). t1 is the motor (thigh) angle the encoder measures.
//  - Inverse kinematics (IK): t3 from the third equation; eliminating t2 leaves a quadratic
//    in tan(t1/2) whose "-" root is the Falcon's configuration; then t2.
//  - Jacobian: implicit differentiation of the closure gives, per leg,
//        dt1/d(u, v, w) = (cos t2, cos t3 / sin t3, sin t2) / (a sin(t2 - t1)),
//    rotated into the kinematic frame. (libnifalcon's FalconKinematicStamper.cpp has
//    sin^2 t2 where this derivation has sin t2 sin t3 in the w column; its JacobianMatrix.cpp
//    agrees with the derivation, and the tests check it against finite differences.)
//  - Forward kinematics (FK): Newton-Raphson on p with that Jacobian until the angle error
//    is below 1e-12 rad. NIF stops at 0.01 rad with half steps; full steps converge
//    quadratically and reach the 1e-6 m the tests ask for in 3-5 iterations.
//  - Force -> motor words: torque = J_p^T F with J_p = dp/dt1; if the largest |torque|
//    exceeds 30 all three scale down to 30 (NIF); times 10000; negated (NIF). Then, our
//    addition, if a word would leave int16 all three scale down together (NIF would wrap
//    the low 16 bits; scaling keeps the force's direction), rounded and clamped.
//
// Positions here are in the Falcon's KINEMATIC frame (metres): z along the grip axis,
// growing as the grip is pulled out toward the user (NIF's cube test: z 0.095..0.155,
// "all the way out" is z > 0.170). falcon_device.h maps it onto device space.
//
// Every function returns an error, never NaN, for positions the model cannot reach or
// singular configurations; nothing allocates.

#include "core/base/status.h"
#include "core/base/vec3.h"

#include <cstdint>

namespace haptics::falcon {

// Geometry (docs/devices/falcon.md, "Kinematics"), metres.
inline constexpr double FALCON_A = 0.060;
inline constexpr double FALCON_B = 0.1025;
inline constexpr double FALCON_C = 0.01443;
inline constexpr double FALCON_D = 0.01125;
inline constexpr double FALCON_E = 0.01125;
inline constexpr double FALCON_F = -0.025;
inline constexpr double FALCON_R = 0.0400;
inline constexpr double FALCON_S = -0.02309;

// Encoder -> thigh angle (docs/devices/falcon.md): shaft 0.01425 m, 320 slots x 4 (quadrature), arm 0.110 m,
// 35 degrees at count 0: theta = 35 deg + 0.0364347 deg * count.
inline constexpr double FALCON_THETA_OFFSET_DEG = 35.0;
inline constexpr double FALCON_DEG_PER_COUNT = (0.01425 / (320.0 * 4.0)) * 360.0 / 0.110;

// NIF's cube test centres its walls on (0, 0, 0.125) (FalconCubeTest.cpp: corners
// (+-0.030, +-0.030, 0.095..0.155)); a 0.05 m sphere around it is reachable in the model.
inline constexpr Vec3 FALCON_KINEMATIC_CENTRE{ 0.0, 0.0, 0.125 };

// NIF's limit on |J^T F| before the x10000 (units undocumented: docs/devices/sources.md) and the scale.
inline constexpr double FALCON_MAX_JOINT_TORQUE = 30.0;
inline constexpr double FALCON_TORQUE_TO_WORD = 10000.0;

struct LegAngles {
	double theta1 = 0.0; // Motor (thigh), rad.
	double theta2 = 0.0;
	double theta3 = 0.0;
};

struct FalconAngles {
	LegAngles leg[3];
};

// Row-major 3x3 matrix: just what the kinematics needs.
struct Mat3 {
	double m[3][3] = {};

	Vec3 operator*(const Vec3 &p_v) const;
	Mat3 transposed() const;
	double determinant() const;
};
// Fails (false) when |det| is below p_min_determinant.
bool invert(const Mat3 &p_matrix, Mat3 &r_inverse, double p_min_determinant = 1e-18);

double encoder_to_theta_deg(int32_t p_count);
double encoder_to_theta_rad(int32_t p_count);
// The nearest count, clamped to int16 (what a real encoder would report); for the scripted
// device.
int16_t theta_rad_to_encoder(double p_theta_rad);

// p_position in the kinematic frame, m. Errors name the leg and why it cannot reach.
Status falcon_inverse_kinematics(const Vec3 &p_position, FalconAngles &r_angles);

// dt1_i/dp (row i: leg i) at a configuration from falcon_inverse_kinematics.
Status falcon_angle_jacobian(const FalconAngles &p_angles, Mat3 &r_dtheta_dp);
// dp/dt1: the inverse of the above, at p_position. Errors near singular configurations.
Status falcon_position_jacobian(const Vec3 &p_position, Mat3 &r_dp_dtheta);

// Motor angles (rad) -> position, starting from p_guess (the previous position keeps it to
// 1-2 iterations while the grip moves). r_iterations (optional) reports the work done.
Status falcon_forward_kinematics(const double p_theta1[3], const Vec3 &p_guess, Vec3 &r_position,
		int32_t *r_iterations = nullptr);

struct MotorWords {
	int16_t word[3] = {};
	bool torque_limited = false; // NIF's |torque| > 30 scaling applied.
	bool word_limited = false; // Our int16 scaling applied.
};

// Force (kinematic frame, N) at p_position -> the three motor words of the command packet.
// Errors for a non-finite force or an unreachable/singular position; r_words untouched then.
Status falcon_force_to_motor_words(const Vec3 &p_position, const Vec3 &p_force_n, MotorWords &r_words);
// The inverse, for the scripted device and tests: the force those words render at
// p_position (exact for words that were not limited, up to rounding).
Status falcon_motor_words_to_force(const Vec3 &p_position, const int16_t p_words[3], Vec3 &r_force_n);

} // namespace haptics::falcon
