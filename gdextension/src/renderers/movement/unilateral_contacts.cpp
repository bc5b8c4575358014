#include "renderers/movement/unilateral_contacts.h"

#include <algorithm>

namespace haptics {

namespace {

// cos(DUPLICATE_ANGLE_RAD) to well below its own size (x^4/24 ~ 4e-14).
constexpr double DUPLICATE_COS = 1.0 - DUPLICATE_ANGLE_RAD * DUPLICATE_ANGLE_RAD / 2.0;
// A contact the free part presses into by less than this (input units, |i| <= 1) is not
// worth a step: it is the rounding error of a contact already accounted for.
constexpr double PRESS_TOLERANCE = 1e-12;
// Gram determinant (1 - cos^2) of two normals, and the volume of three, below which they
// are taken as dependent: 1e-12 is an angle of 1e-6 rad, far inside DUPLICATE_ANGLE_RAD.
constexpr double DEPENDENT_PAIR = 1e-12;
constexpr double DEPENDENT_TRIPLE = 1e-9;
// Independent directions in device space: at most this many contacts are ever active.
constexpr uint32_t MAX_ACTIVE = 3;
// Lawson-Hanson adds one contact per step and never revisits an active set; this bounds it
// anyway, whatever rounding does.
constexpr uint32_t MAX_STEPS = 3 * MAX_CONTACTS;

// The multipliers z minimising |x + sum_a z_a n_a|^2 over the active contacts, without the
// sign constraint; false when their normals are (numerically) dependent.
bool solve_active(const Vec3 *p_normals, const uint32_t *p_active, uint32_t p_count, const Vec3 &p_input,
		double *r_z) {
	if (p_count == 1) {
		r_z[0] = -dot(p_normals[p_active[0]], p_input);
		return true;
	}
	if (p_count == 2) {
		const Vec3 &n0 = p_normals[p_active[0]];
		const Vec3 &n1 = p_normals[p_active[1]];
		const double c = dot(n0, n1);
		const double det = 1.0 - c * c;
		if (det < DEPENDENT_PAIR) {
			return false;
		}
		const double d0 = -dot(n0, p_input);
		const double d1 = -dot(n1, p_input);
		r_z[0] = (d0 - c * d1) / det;
		r_z[1] = (d1 - c * d0) / det;
		return true;
	}
	// Three independent normals span the space: -sum z_a n_a = x exactly (Cramer's rule).
	const Vec3 &n0 = p_normals[p_active[0]];
	const Vec3 &n1 = p_normals[p_active[1]];
	const Vec3 &n2 = p_normals[p_active[2]];
	const double volume = dot(n0, cross(n1, n2));
	if (std::abs(volume) < DEPENDENT_TRIPLE) {
		return false;
	}
	r_z[0] = -dot(p_input, cross(n1, n2)) / volume;
	r_z[1] = -dot(p_input, cross(n2, n0)) / volume;
	r_z[2] = -dot(p_input, cross(n0, n1)) / volume;
	return true;
}

void remove_active(uint32_t *r_active, uint32_t &r_count, uint32_t p_position) {
	for (uint32_t a = p_position; a + 1 < r_count; ++a) {
		r_active[a] = r_active[a + 1];
	}
	--r_count;
}

// Distinct unit normals with their averaged materials. While gathering, normals[m] holds the
// sum of cluster m's unit normals, and a normal joins the first cluster whose mean direction
// is within DUPLICATE_ANGLE_RAD of it.
void gather(const Frame &p_frame, const ContactMaterial &p_default_material, UnilateralContacts &r_contacts) {
	uint32_t members[MAX_CONTACTS];
	r_contacts.count = 0;
	for (uint32_t c = 0; c < p_frame.contacts.size() && c < MAX_CONTACTS; ++c) {
		const Contact &contact = p_frame.contacts[c];
		const Vec3 n = normalized_or_zero(contact.normal);
		if (!is_finite(n) || n == Vec3{}) {
			continue;
		}
		const ContactMaterial &material = contact.material.value_or(p_default_material);
		uint32_t m = 0;
		while (m < r_contacts.count &&
				dot(r_contacts.normals[m], n) < DUPLICATE_COS * length(r_contacts.normals[m])) {
			++m;
		}
		if (m == r_contacts.count) {
			++r_contacts.count;
			r_contacts.normals[m] = Vec3{};
			r_contacts.materials[m] = ContactMaterial{ 0.0, 0.0 };
			members[m] = 0;
		}
		r_contacts.normals[m] += n;
		r_contacts.materials[m].stiffness_n += material.stiffness_n;
		r_contacts.materials[m].friction_n += material.friction_n;
		++members[m];
	}
	for (uint32_t m = 0; m < r_contacts.count; ++m) {
		r_contacts.normals[m] = normalized_or_zero(r_contacts.normals[m]);
		r_contacts.materials[m].stiffness_n /= members[m];
		r_contacts.materials[m].friction_n /= members[m];
	}
}

} // namespace

void resolve_unilateral(const Frame &p_frame, const Vec3 &p_input, const ContactMaterial &p_default_material,
		UnilateralContacts &r_contacts) {
	gather(p_frame, p_default_material, r_contacts);
	double *lambda = r_contacts.pushes;
	std::fill(lambda, lambda + MAX_CONTACTS, 0.0);
	r_contacts.blocked = Vec3{};
	r_contacts.free = p_input;
	if (!is_finite(p_input)) {
		return;
	}
	const Vec3 *normals = r_contacts.normals;
	uint32_t active[MAX_ACTIVE] = {};
	uint32_t active_count = 0;
	uint32_t active_mask = 0; // Bit j: contact j is in active[].
	uint32_t excluded = 0; // Bit j: contact j is dependent on the active ones; skip it.
	static_assert(MAX_CONTACTS <= 32);
	Vec3 blocked;
	for (uint32_t step = 0; step < MAX_STEPS && active_count < MAX_ACTIVE; ++step) {
		// Lawson-Hanson: activate the contact the free part presses into hardest...
		const Vec3 free = p_input - blocked;
		uint32_t best = MAX_CONTACTS;
		double best_press = PRESS_TOLERANCE;
		for (uint32_t j = 0; j < r_contacts.count; ++j) {
			const double press = -dot(normals[j], free);
			if (!((active_mask | excluded) & (1u << j)) && press > best_press) {
				best = j;
				best_press = press;
			}
		}
		if (best == MAX_CONTACTS) {
			break; // Nothing pressed: the KKT conditions hold.
		}
		active[active_count++] = best;
		active_mask |= 1u << best;
		// ...then solve on the active set, backing off toward the last feasible multipliers
		// whenever one would turn negative (a contact that would pull) and dropping it.
		for (uint32_t inner = 0; inner <= MAX_ACTIVE && active_count > 0; ++inner) {
			double z[MAX_ACTIVE];
			const bool solved = solve_active(normals, active, active_count, p_input, z);
			const bool added_pulls = inner == 0 && solved && z[active_count - 1] <= 0.0;
			if (!solved || added_pulls) {
				// Dependent on the active contacts, or rounding made it look pressed: either
				// way it adds nothing. Skipping it for the rest of the solve ends the loop.
				for (uint32_t a = 0; a < active_count; ++a) {
					if (active[a] == best) {
						lambda[best] = 0.0;
						remove_active(active, active_count, a);
						break;
					}
				}
				active_mask &= ~(1u << best);
				excluded |= 1u << best;
				break;
			}
			double alpha = 1.0;
			for (uint32_t a = 0; a < active_count; ++a) {
				const double current = lambda[active[a]];
				if (z[a] <= 0.0) {
					alpha = std::min(alpha, current / (current - z[a]));
				}
			}
			for (uint32_t a = 0; a < active_count; ++a) {
				lambda[active[a]] += alpha * (z[a] - lambda[active[a]]);
			}
			if (alpha == 1.0) {
				break; // Every active contact pushes: z is the active set's answer.
			}
			for (uint32_t a = active_count; a-- > 0;) {
				if (z[a] <= 0.0 && lambda[active[a]] <= PRESS_TOLERANCE) {
					lambda[active[a]] = 0.0;
					active_mask &= ~(1u << active[a]);
					remove_active(active, active_count, a);
				}
			}
		}
		blocked = Vec3{};
		for (uint32_t a = 0; a < active_count; ++a) {
			blocked -= normals[active[a]] * lambda[active[a]];
		}
	}
	r_contacts.blocked = blocked;
	r_contacts.free = p_input - blocked;
}

} // namespace haptics
