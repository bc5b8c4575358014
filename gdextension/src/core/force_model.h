#pragma once

// Movement-based force model (Bowman & al., "A Movement Based Method for Haptic
// Interaction", eqs. 1-7), evaluated at every servo tick from the latest frame and a fresh
// input vector. Pure functions of their arguments: no state, no allocation.
//
// Device space throughout (coordinates.h), d = DEVICE_DOWN = (0, -1, 0). Forces in newtons.
//
//   i   = input vector (input_vector below), dimensionless, |i| <= 1
//   n   = normalised sum of the unit contact normals; no contact (or normals cancelling
//         out, |sum| < 1e-6) means no normal and no friction force
//   p   = (i.n / |n|^2) n             projection       (eq. 1)
//   r   = i - p                       rejection        (eq. 2)
//   F_n = -k p                        normal force     (eq. 3)
//   F_f = -b r                        friction         (eq. 4)
//   W   = sum_j m_j g (n_j.d) d       weight, only the objects with n_j.d > 0  (eq. 5)
//   F_d = -c v                        water drag, only inside water            (eq. 6)
//   F_w = w d                         water inertia, only inside water         (eq. 7)
//
// Several contacts: each contact j has its own k_j, b_j. The rendered k and b are the
// averages weighted by how much each contact faces the combined normal,
// s_j = max(0, n_j.n): a floor and a wall in a corner count equally (45 degree normal),
// while a contact whose normal points away from the combined normal (a grazing ceiling
// while standing in a corner) does not soften or stiffen the result. With one contact this
// is just that contact's material. Averaging rather than max keeps the force continuous when
// contacts appear and disappear at 50 Hz.
//
// Weight uses each resting object's own normal (normalised), not the combined contact
// normal, so a crate on the head is felt whatever else the player touches.

#include "core/config.h"
#include "core/frame.h"
#include "core/vec3.h"

namespace haptics {

// Every component separately, for the HUD and telemetry. The force model fills the first
// six; the servo pipeline fills the rest.
struct ForceComponents {
	Vec3 normal; // F_n
	Vec3 friction; // F_f
	Vec3 weight; // W
	Vec3 drag; // F_d
	Vec3 inertia; // F_w
	Vec3 continuous; // F_n + F_f + W + F_d + F_w, before smoothing
	Vec3 smoothed; // continuous after smoothing, slew limit and watchdog fade
	Vec3 impact; // Sum of the impact transients, raw (not smoothed)
	Vec3 total; // What was written to the device: ramp and clamp applied
};

// The force model's intermediate results, useful for tests and debugging.
struct ContactResolution {
	bool active = false; // False without contacts or when their normals cancel out.
	Vec3 normal; // Unit combined normal n (zero when !active).
	double stiffness = 0.0; // Combined k, N per unit input.
	double friction = 0.0; // Combined b, N per unit input.
};

// Device position (m) -> input vector. Divides by p_radius_m, clamps to the unit ball, then
// applies the dead zone: |i| <= dz gives 0, otherwise |i| is remapped (|i| - dz) / (1 - dz)
// keeping the direction, so the output is continuous at the dead-zone edge and still
// reaches 1 at the workspace edge. p_radius_m > 0, p_dead_zone in [0, 1).
Vec3 input_vector(const Vec3 &p_position_m, double p_radius_m, double p_dead_zone);

ContactResolution resolve_contacts(const Frame &p_frame, const ContactMaterial &p_default_material);

// Fills normal, friction, weight, drag, inertia and continuous of the result; the other
// fields are zero. The frame must be valid (validate_frame); p_input is the input vector.
ForceComponents compute_forces(const Frame &p_frame, const Vec3 &p_input, const ForceModelConfig &p_config);
// The same, written over those six fields of r_forces in place (the others are left as they
// are): what the servo tick uses, so it neither builds nor copies a whole ForceComponents.
void compute_forces(const Frame &p_frame, const Vec3 &p_input, const ForceModelConfig &p_config,
		ForceComponents &r_forces);

} // namespace haptics
