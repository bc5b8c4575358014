#include "renderers/movement/force_model.h"

#include "core/base/coordinates.h"
#include "renderers/movement/unilateral_contacts.h"

#include <algorithm>

namespace haptics {

namespace {

// Contact normals summing to less than this are treated as cancelling out: the combined
// direction would be numerical noise.
constexpr double NORMAL_SUM_EPSILON = 1e-6;

// PAPER_SUM: eqs. 1-4 on the combined contact.
void paper_sum_forces(const Frame &p_frame, const Vec3 &p_input, const ForceModelConfig &p_config, Vec3 &r_normal,
		Vec3 &r_friction) {
	const ContactResolution contact = resolve_contacts(p_frame, p_config.default_contact);
	if (contact.active) {
		const Vec3 &n = contact.normal;
		const Vec3 projection = n * (dot(p_input, n) / length_squared(n));
		const Vec3 rejection = p_input - projection;
		r_normal = projection * -contact.stiffness;
		r_friction = rejection * -contact.friction;
	}
}

// PER_CONTACT: each contact answers the part of the input it blocks (force_model.h).
void per_contact_forces(const Frame &p_frame, const Vec3 &p_input, const ForceModelConfig &p_config, Vec3 &r_normal,
		Vec3 &r_friction) {
	UnilateralContacts contacts;
	resolve_unilateral(p_frame, p_input, p_config.default_contact, contacts);
	double rubbing = 0.0; // sum_j b_j clamp((lambda_j - w) / e, 0, 1)
	const double band = p_config.friction_band;
	const double engage = p_config.friction_engage;
	for (uint32_t j = 0; j < contacts.count; ++j) {
		const double push = contacts.pushes[j];
		if (push > 0.0) {
			const ContactMaterial &material = contacts.materials[j];
			r_normal += contacts.normals[j] * (material.stiffness_n * push);
			const double past_band = push - band;
			if (past_band > 0.0) {
				rubbing += material.friction_n * (engage > 0.0 ? std::min(1.0, past_band / engage) : 1.0);
			}
		}
	}
	if (rubbing > 0.0) {
		r_friction = contacts.free * -rubbing;
	}
}

} // namespace

ContactResolution resolve_contacts(const Frame &p_frame, const ContactMaterial &p_default_material) {
	ContactResolution result;
	Vec3 sum;
	for (uint32_t c = 0; c < p_frame.contacts.size(); ++c) {
		sum += normalized_or_zero(p_frame.contacts[c].normal);
	}
	const double sum_length = length(sum);
	if (sum_length < NORMAL_SUM_EPSILON) {
		return result;
	}
	result.active = true;
	result.normal = sum / sum_length;

	double weight_total = 0.0;
	for (uint32_t c = 0; c < p_frame.contacts.size(); ++c) {
		const Contact &contact = p_frame.contacts[c];
		const double share = std::max(0.0, dot(normalized_or_zero(contact.normal), result.normal));
		const ContactMaterial &material = contact.material.value_or(p_default_material);
		result.stiffness += share * material.stiffness_n;
		result.friction += share * material.friction_n;
		weight_total += share;
	}
	// weight_total >= sum_length > 0: the shares sum to at least n.(sum of normals).
	result.stiffness /= weight_total;
	result.friction /= weight_total;
	return result;
}

namespace {

// Both compute_forces: each component written once, where the caller keeps it.
void compute_into(const Frame &p_frame, const Vec3 &p_input, const ForceModelConfig &p_config, Vec3 &r_normal,
		Vec3 &r_friction, Vec3 &r_weight, Vec3 &r_drag, Vec3 &r_inertia, Vec3 &r_continuous) {
	r_normal = Vec3{};
	r_friction = Vec3{};
	switch (p_config.contact_model) {
		case ContactModel::PAPER_SUM:
			paper_sum_forces(p_frame, p_input, p_config, r_normal, r_friction);
			break;
		case ContactModel::PER_CONTACT:
			per_contact_forces(p_frame, p_input, p_config, r_normal, r_friction);
			break;
	}

	r_weight = Vec3{};
	for (uint32_t j = 0; j < p_frame.resting.size(); ++j) {
		const RestingObject &object = p_frame.resting[j];
		const double n_dot_d = dot(normalized_or_zero(object.normal), DEVICE_DOWN);
		if (n_dot_d > 0.0) {
			r_weight += DEVICE_DOWN * (object.mass_kg * p_config.gravity_n_per_kg * n_dot_d);
		}
	}

	r_drag = Vec3{};
	r_inertia = Vec3{};
	if (p_frame.in_water) {
		r_drag = p_frame.velocity_m_per_s * -p_frame.water_drag_n_s_per_m;
		r_inertia = DEVICE_DOWN * p_frame.water_inertia_n;
	}

	r_continuous = r_normal + r_friction + r_weight + r_drag + r_inertia;
}

} // namespace

MovementForces compute_forces(const Frame &p_frame, const Vec3 &p_input, const ForceModelConfig &p_config) {
	MovementForces forces;
	compute_into(p_frame, p_input, p_config, forces.normal, forces.friction, forces.weight, forces.drag, forces.inertia,
			forces.continuous);
	return forces;
}

void compute_forces(const Frame &p_frame, const Vec3 &p_input, const ForceModelConfig &p_config,
		ForceComponents &r_forces) {
	auto &parts = r_forces.parts;
	compute_into(p_frame, p_input, p_config, parts[NORMAL_FORCE], parts[FRICTION_FORCE], parts[WEIGHT_FORCE],
			parts[DRAG_FORCE], parts[INERTIA_FORCE], r_forces.continuous);
}

} // namespace haptics
