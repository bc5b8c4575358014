#include "core/validation.h"

#include "core/config_fields.h"
#include "pong/pong_validation.h"

#include <cmath>
#include <cstdio>

namespace haptics {

namespace {

constexpr double MAX_MASS_KG = 1000.0;
constexpr double MAX_SPEED_M_PER_S = 1000.0;
// Normals shorter than this carry no direction.
constexpr double MIN_DIRECTION_LENGTH = 1e-6;

} // namespace

Status check_range(const char *p_name, double p_value, double p_min, double p_max) {
	if (!std::isfinite(p_value)) {
		return Status::error(StatusCode::INVALID_ARGUMENT, "%s: not finite (%g)", p_name, p_value);
	}
	if (p_value < p_min || p_value > p_max) {
		return Status::error(StatusCode::OUT_OF_RANGE, "%s must be in [%g, %g] (got %g)", p_name, p_min, p_max, p_value);
	}
	return Status::success();
}

Status check_vector(const char *p_name, const Vec3 &p_value, bool p_nonzero, double p_max_length) {
	if (!is_finite(p_value)) {
		return Status::error(StatusCode::INVALID_ARGUMENT, "%s: not finite (%g, %g, %g)", p_name, p_value.x, p_value.y,
				p_value.z);
	}
	const double len = length(p_value);
	if (p_nonzero && len < MIN_DIRECTION_LENGTH) {
		return Status::error(StatusCode::INVALID_ARGUMENT, "%s: zero length, a direction is needed", p_name);
	}
	if (len > p_max_length) {
		return Status::error(StatusCode::OUT_OF_RANGE, "%s: length must be <= %g (got %g)", p_name, p_max_length, len);
	}
	return Status::success();
}

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

Status validate_render_config(const RenderConfig &p_config) {
	for (const ConfigField &field : config_fields()) {
		HAPTICS_RETURN_IF_ERROR(check_config_value(field, field.get(p_config)));
	}
	HAPTICS_RETURN_IF_ERROR(validate_pong_config(p_config.pong));
	const auto mode = static_cast<size_t>(p_config.render_mode);
	if (mode >= RENDER_MODE_COUNT) {
		return Status::error(StatusCode::INVALID_ARGUMENT, "render_mode: unknown mode %d",
				static_cast<int>(p_config.render_mode));
	}
	return Status::success();
}

Status validate_rate(double p_rate_hz) {
	return check_range("rate_hz", p_rate_hz, MIN_RATE_HZ, MAX_RATE_HZ);
}

Status validate_step_dt(double p_dt_s) {
	return check_range("dt", p_dt_s, 1.0 / MAX_RATE_HZ, 1.0 / MIN_RATE_HZ);
}

} // namespace haptics
