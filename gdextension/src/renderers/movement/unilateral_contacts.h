#pragma once

// The geometry of the per-contact model (force_model.h, ContactModel::PER_CONTACT): which
// part of the input vector the frame's contacts block, and how much each contact pushes.
//
// Every contact j is a one-sided constraint on the input's direction: with n_j its unit
// normal (from the surface toward the player), the input may point anywhere with
// i.n_j >= 0, never into the surface. The free cone C = { v : v.n_j >= 0 for every j } is
// what the contacts let through. The input splits uniquely (Moreau) into
//
//   a = proj_C(i)                   free part: what the player may still do (slide)
//   b = i - a = -sum_j lambda_j n_j  blocked part, lambda_j >= 0, a.b = 0,
//                                    lambda_j > 0 only where a.n_j = 0
//
// i.e. lambda = argmin |i + sum_j lambda_j n_j|^2 subject to lambda >= 0 (non-negative least
// squares, solved here by Lawson-Hanson's active set). lambda_j is the push contact j gives:
// a constraint solver's contact multiplier. It is the pressing depth d_j = max(0, -i.n_j)
// for one contact and for mutually orthogonal ones (a 90 degree corner), but not otherwise:
// pressing straight down where a floor meets a 45 degree ramp blocks the input once (the
// floor's lambda is 1, the ramp's 0), where summing the depths would push 1.6 times and
// sideways; in an acute wedge a contact the input does not press directly (i.n_j > 0) can
// still hold it.
//
// Unique as b is, lambda is not when more contacts are active than the space has
// dimensions: the solver keeps at most three independent contacts active. Contacts whose
// normals are within DUPLICATE_ANGLE_RAD of each other (one surface reported twice: two
// tiles, two colliders sharing a face) are merged first, their materials averaged, so that
// such a surface has one well-defined material rather than whichever came first. The
// blocked part never doubles either way: two equal normals leave the same free cone as one.
//
// Fixed-size arrays, no allocation: cheap enough for every servo tick (a handful of dot
// products per contact; a few active-set steps).

#include "core/base/vec3.h"
#include "core/render/frame.h"

#include <cstdint>

namespace haptics {

// Normals closer than this (radians) are one surface. Physics engines report one plane's
// normal to ~1e-7; distinct surfaces of game geometry differ by degrees.
inline constexpr double DUPLICATE_ANGLE_RAD = 1e-3;

struct UnilateralContacts {
	uint32_t count = 0; // Distinct contacts, after merging duplicates and dropping degenerate ones.
	Vec3 normals[MAX_CONTACTS]; // Unit.
	ContactMaterial materials[MAX_CONTACTS]; // Averaged over merged duplicates.
	double pushes[MAX_CONTACTS] = {}; // lambda_j >= 0, input units.
	Vec3 blocked; // b = -sum_j lambda_j n_j.
	Vec3 free; // a = i - b.
};

// Contacts whose normal is zero or not finite are skipped (validate_frame refuses them; this
// keeps a frame that bypassed it from poisoning the result). A non-finite input is pressed
// into nothing: no pushes, and the free part is the input as it is.
void resolve_unilateral(const Frame &p_frame, const Vec3 &p_input, const ContactMaterial &p_default_material,
		UnilateralContacts &r_contacts);

} // namespace haptics
