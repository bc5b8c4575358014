#include "core/render/frame_validation.h"

#include "core/base/value_checks.h"

#include <cstdio>

namespace haptics {

namespace {

constexpr double MAX_MASS_KG = 1000.0;
constexpr double MAX_SPEED_M_PER_S = 1000.0;

} // namespace

Status validate_contact_material(const char *p_name, const ContactMaterial &p_material) {
	char name[96];
	std::snprintf(name, sizeof(name), "%s.stiffness", p_name);
	HAPTICS_RETURN_IF_ERROR(check_range(name, p_material.stiffness, 0.0, MAX_GAIN));
	std::snprintf(name, sizeof(name), "%s.friction", p_name);
	return check_range(name, p_material.friction, 0.0, MAX_GAIN);
}

Status validate_impact_material(const char *p_name, const ImpactMaterial &p_material) {
	char name[96];
	std::snprintf(name, sizeof(name), "%s.gain", p_name);
	HAPTICS_RETURN_IF_ERROR(check_range(name, p_material.gain, 0.0, MAX_GAIN));
	std::snprintf(name, sizeof(name), "%s.frequency_hz", p_name);
	HAPTICS_RETURN_IF_ERROR(check_range(name, p_material.frequency_hz, MIN_IMPACT_FREQUENCY_HZ, MAX_IMPACT_FREQUENCY_HZ));
	std::snprintf(name, sizeof(name), "%s.decay_s", p_name);
	return check_range(name, p_material.decay_s, MIN_IMPACT_DECAY_S, MAX_IMPACT_DECAY_S);
}

Status validate_frame(const Frame &p_frame) {
	if (p_frame.contact_count > MAX_CONTACTS) {
		return Status::error(StatusCode::OUT_OF_RANGE, "frame.contact_count must be <= %zu (got %u)", MAX_CONTACTS,
				p_frame.contact_count);
	}
	if (p_frame.resting_count > MAX_RESTING_OBJECTS) {
		return Status::error(StatusCode::OUT_OF_RANGE, "frame.resting_count must be <= %zu (got %u)",
				MAX_RESTING_OBJECTS, p_frame.resting_count);
	}
	char name[96];
	for (uint32_t c = 0; c < p_frame.contact_count; ++c) {
		const Contact &contact = p_frame.contacts[c];
		std::snprintf(name, sizeof(name), "frame.contacts[%u].normal", c);
		HAPTICS_RETURN_IF_ERROR(check_vector(name, contact.normal, true, 1e6));
		if (!contact.use_default_material) {
			std::snprintf(name, sizeof(name), "frame.contacts[%u].material", c);
			HAPTICS_RETURN_IF_ERROR(validate_contact_material(name, contact.material));
		}
	}
	for (uint32_t r = 0; r < p_frame.resting_count; ++r) {
		const RestingObject &object = p_frame.resting[r];
		std::snprintf(name, sizeof(name), "frame.resting[%u].normal", r);
		HAPTICS_RETURN_IF_ERROR(check_vector(name, object.normal, true, 1e6));
		std::snprintf(name, sizeof(name), "frame.resting[%u].mass", r);
		HAPTICS_RETURN_IF_ERROR(check_range(name, object.mass, 0.0, MAX_MASS_KG));
	}
	HAPTICS_RETURN_IF_ERROR(check_range("frame.water.drag", p_frame.water.drag, 0.0, MAX_GAIN));
	HAPTICS_RETURN_IF_ERROR(check_range("frame.water.inertia", p_frame.water.inertia, -MAX_GAIN, MAX_GAIN));
	HAPTICS_RETURN_IF_ERROR(check_vector("frame.player_velocity", p_frame.player_velocity, false, MAX_SPEED_M_PER_S));
	return check_range("frame.timestamp_s", p_frame.timestamp_s, -1e12, 1e12);
}

Status validate_impact(const ImpactEvent &p_event) {
	HAPTICS_RETURN_IF_ERROR(check_vector("impact.direction", p_event.direction, true, 1e6));
	HAPTICS_RETURN_IF_ERROR(check_range("impact.speed", p_event.speed, 0.0, MAX_SPEED_M_PER_S));
	if (!p_event.use_default_material) {
		return validate_impact_material("impact.material", p_event.material);
	}
	return Status::success();
}

} // namespace haptics
