#pragma once

// Movement-based force model (Bowman & al., "A Movement Based Method for Haptic
// Interaction", eqs. 1-7), evaluated at every servo tick from the latest frame and a fresh
// input vector. Pure functions of their arguments: no state, no allocation.
//
// Device space throughout (coordinates.h), d = DEVICE_DOWN = (0, -1, 0). Forces in newtons.
// i = input vector (input_vector below), dimensionless, |i| <= 1; n_j = unit normal of
// contact j (from the surface toward the player), with its material k_j, b_j.
//
// Weight, water drag and inertia are the paper's in both contact models:
//   W   = sum_j m_j g (n_j.d) d       weight, only the objects with n_j.d > 0  (eq. 5)
//   F_d = -c v                        water drag, only inside water            (eq. 6)
//   F_w = w d                         water inertia, only inside water         (eq. 7)
// Weight uses each resting object's own normal (normalised), not a contact normal, so a
// crate on the head is felt whatever else the player touches.
//
// Normal force and friction: ForceModelConfig::contact_model chooses.
//
// PAPER_SUM, the paper's literal eqs. 1-4:
//   n   = normalised sum of the n_j; no contact (or normals cancelling out, |sum| < 1e-6)
//         means no normal and no friction force
//   p   = (i.n / |n|^2) n             projection       (eq. 1)
//   r   = i - p                       rejection        (eq. 2)
//   F_n = -k p                        normal force     (eq. 3)
//   F_f = -b r                        friction         (eq. 4)
// k and b are the contacts' averages weighted by s_j = max(0, n_j.n) (resolve_contacts).
// Two artefacts are felt on a real device: F_n does not care about the sign of i.n, so
// pointing away from a wall that is still in contact pulls the hand into it until a frame
// shows the body off the wall (at most two 50 Hz frames if the body keeps no velocity into
// a wall once blocked, as the project's avatar does, game/player/player.gd; a body that
// keeps its speed into the wall is held there, and pulls, for as long as it takes to
// reverse); and a floor plus a wall give a 45 degree normal, so a horizontal push into the
// wall while standing is answered with k |i| / 2 upward, which nobody pushed for.
//
// PER_CONTACT (the default): every contact is a one-sided constraint on the input and
// answers only the part of the input it blocks (unilateral_contacts.h):
//   a   = proj_C(i), C = { v : v.n_j >= 0 }    free part: the motion the contacts allow
//   b   = i - a = -sum_j lambda_j n_j         blocked part, lambda_j >= 0 per contact
//   F_n = sum_j k_j lambda_j n_j              each contact pushes along its own normal
//   F_f = -(sum_j b_j clamp((lambda_j - w) / e, 0, 1)) a  friction against the sliding
// with w = ForceModelConfig::friction_band, e = friction_engage. Why this way:
// - One contact pressed (i.n < 0): lambda = -i.n, a = r, so F_n = -k p and, once
//   lambda >= w + e, F_f = -b r: exactly the paper's eqs. 3-4.
// - Pulling away (i.n_j >= 0 for all j): a = i, nothing is blocked, no force. No pull into
//   the wall, and no friction for an input that slides along a floor without pressing it
//   (the paper's -b r would resist walking along a floor in proportion to the input).
// - Floor plus wall, horizontal push into the wall: the floor blocks nothing (lambda = 0),
//   F_n = k_wall |i| along the wall's normal: exactly the wall's push-back.
// - 90 degree corner, input into both: lambda_j = d_j = -i.n_j, each contact pushes back
//   its own component with its own k (with equal k: -k i, as the paper's model).
// - Other corners: lambda is what a constraint solver's contact multipliers are, not the
//   depths d_j (summing those would push 1.6 |i| sideways where a floor meets a 45 degree
//   ramp and the input points straight down); in an acute wedge a contact the input does
//   not press directly can still hold it.
// - Opposed contacts (squeezed between two walls): the input presses into one of them,
//   which pushes back; the paper's normals cancel and render nothing.
// - Duplicates (one surface reported twice) are merged: no doubled force, one material.
// - Friction: a is the sliding the contacts allow, tangential to every active contact
//   (a.n_j = 0 when lambda_j > 0); pressed into a corner there is no sliding and no
//   friction, as in the paper's model. Each contact rubs with its own b, and only once it
//   is pressed past the band w: a hand held at a floor's plane trembles a few per cent
//   either way, and friction must not switch on and off with it. Past w it fades in over e,
//   growing continuously from zero instead of jumping to b |r|; contacts that push nothing
//   add nothing.
// - Continuity: a and b are continuous in i (a projection); a contact that appears without
//   being pressed changes nothing, and one that is pressed starts from lambda = 0.

#include "core/base/vec3.h"
#include "core/render/force_components.h"
#include "core/render/frame.h"
#include "renderers/movement/movement.gen.h"
#include "renderers/movement/movement_config.h"

#include <cstddef>
#include <iterator>

namespace haptics {

// The components, in their order in ForceComponents::parts (MovementForce, movement.schema.toml):
// F_n, F_f, W, F_d, F_w.
static_assert(MOVEMENT_FORCE_COUNT <= MAX_FORCE_PARTS);

// The components by name, for tests and tools that evaluate the model alone.
struct MovementForces {
	Vec3 normal;
	Vec3 friction;
	Vec3 weight;
	Vec3 drag;
	Vec3 inertia;
	Vec3 continuous; // F_n + F_f + W + F_d + F_w, before smoothing
};

// The paper's combined contact (PAPER_SUM), useful for tests and debugging.
struct ContactResolution {
	bool active = false; // False without contacts or when their normals cancel out.
	Vec3 normal; // Unit combined normal n (zero when !active).
	double stiffness = 0.0; // Combined k, N per unit input.
	double friction = 0.0; // Combined b, N per unit input.
};

// PAPER_SUM's n, k and b.
ContactResolution resolve_contacts(const Frame &p_frame, const ContactMaterial &p_default_material);

// The five components and their sum. The frame must be valid (validate_frame); p_input is
// the input vector (core/servo/input_vector.h).
MovementForces compute_forces(const Frame &p_frame, const Vec3 &p_input, const ForceModelConfig &p_config);
// The same, written over the five parts and `continuous` of r_forces in place (the others
// are left as they are): what the servo tick uses, so it neither builds nor copies a whole
// ForceComponents.
void compute_forces(const Frame &p_frame, const Vec3 &p_input, const ForceModelConfig &p_config,
		ForceComponents &r_forces);

} // namespace haptics
