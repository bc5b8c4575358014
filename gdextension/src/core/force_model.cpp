#include "core/force_model.h"

#include "core/coordinates.h"
#include "core/unilateral_contacts.h"

#include <algorithm>

namespace haptics {

namespace {

// Contact normals summing to less than this are treated as cancelling out: the combined
// direction would be numerical noise.
constexpr double NORMAL_SUM_EPSILON = 1e-6;

} // namespace

Vec3 input_vector(const Vec3 &p_position_m, double p_radius_m, double p_dead_zone) {
	const Vec3 raw = p_position_m / p_radius_m;
	const double magnitude = length(raw);
	if (!(magnitude > p_dead_zone) || magnitude <= 0.0) {
		return {};
	}
	const double clamped = std::min(magnitude, 1.0);
	const double rescaled = (clamped - p_dead_zone) / (1.0 - p_dead_zone);
	return raw * (rescaled / magnitude);
}

namespace {

// PAPER_SUM: eqs. 1-4 on the combined contact.
void paper_sum_forces(const Frame &p_frame, const Vec3 &p_input, const ForceModelConfig &p_config,
		ForceComponents &r_forces) {
	const ContactResolution contact = resolve_contacts(p_frame, p_config.default_contact);
	if (contact.active) {
		const Vec3 &n = contact.normal;
		const Vec3 projection = n * (dot(p_input, n) / length_squared(n));
		const Vec3 rejection = p_input - projection;
		r_forces.normal = projection * -contact.stiffness;
		r_forces.friction = rejection * -contact.friction;
	}
}

// PER_CONTACT: each contact answers the part of the input it blocks (force_model.h).
void per_contact_forces(const Frame &p_frame, const Vec3 &p_input, const ForceModelConfig &p_config,
		ForceComponents &r_forces) {
	UnilateralContacts contacts;
	resolve_unilateral(p_frame, p_input, p_config.default_contact, contacts);
	double rubbing = 0.0; // sum_j b_j min(1, lambda_j / e)
	const double engage = p_config.friction_engage;
	for (uint32_t j = 0; j < contacts.count; ++j) {
		const double push = contacts.pushes[j];
		if (push > 0.0) {
			const ContactMaterial &material = contacts.materials[j];
			r_forces.normal += contacts.normals[j] * (material.stiffness * push);
			rubbing += material.friction * (engage > 0.0 ? std::min(1.0, push / engage) : 1.0);
		}
	}
	if (rubbing > 0.0) {
		r_forces.friction = contacts.free * -rubbing;
	}
}

} // namespace

ContactResolution resolve_contacts(const Frame &p_frame, const ContactMaterial &p_default_material) {
	ContactResolution result;
	Vec3 sum;
	for (uint32_t c = 0; c < p_frame.contact_count; ++c) {
		sum += normalized_or_zero(p_frame.contacts[c].normal);
	}
	const double sum_length = length(sum);
	if (sum_length < NORMAL_SUM_EPSILON) {
		return result;
	}
	result.active = true;
	result.normal = sum / sum_length;

	double weight_total = 0.0;
	for (uint32_t c = 0; c < p_frame.contact_count; ++c) {
		const Contact &contact = p_frame.contacts[c];
		const double share = std::max(0.0, dot(normalized_or_zero(contact.normal), result.normal));
		const ContactMaterial &material = contact.use_default_material ? p_default_material : contact.material;
		result.stiffness += share * material.stiffness;
		result.friction += share * material.friction;
		weight_total += share;
	}
	// weight_total >= sum_length > 0: the shares sum to at least n.(sum of normals).
	result.stiffness /= weight_total;
	result.friction /= weight_total;
	return result;
}

ForceComponents compute_forces(const Frame &p_frame, const Vec3 &p_input, const ForceModelConfig &p_config) {
	ForceComponents forces;
	compute_forces(p_frame, p_input, p_config, forces);
	return forces;
}

void compute_forces(const Frame &p_frame, const Vec3 &p_input, const ForceModelConfig &p_config,
		ForceComponents &r_forces) {
	r_forces.normal = Vec3{};
	r_forces.friction = Vec3{};
	switch (p_config.contact_model) {
		case ContactModel::PAPER_SUM:
			paper_sum_forces(p_frame, p_input, p_config, r_forces);
			break;
		case ContactModel::PER_CONTACT:
			per_contact_forces(p_frame, p_input, p_config, r_forces);
			break;
	}

	r_forces.weight = Vec3{};
	for (uint32_t j = 0; j < p_frame.resting_count; ++j) {
		const RestingObject &object = p_frame.resting[j];
		const double n_dot_d = dot(normalized_or_zero(object.normal), DEVICE_DOWN);
		if (n_dot_d > 0.0) {
			r_forces.weight += DEVICE_DOWN * (object.mass * p_config.gravity_n_per_kg * n_dot_d);
		}
	}

	r_forces.drag = Vec3{};
	r_forces.inertia = Vec3{};
	if (p_frame.water.inside) {
		r_forces.drag = p_frame.player_velocity * -p_frame.water.drag;
		r_forces.inertia = DEVICE_DOWN * p_frame.water.inertia;
	}

	r_forces.continuous = r_forces.normal + r_forces.friction + r_forces.weight + r_forces.drag + r_forces.inertia;
}

} // namespace haptics
