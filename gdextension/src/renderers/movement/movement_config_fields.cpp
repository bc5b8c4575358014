#include "renderers/movement/movement_renderer.h"

#include "core/config/config_field_access.h"

namespace haptics {

namespace {

#define MOVEMENT_FIELD(path) HAPTICS_CONFIG_FIELD(MovementConfig, path)

using K = FieldKind;

const ConfigField FIELDS[] = {
	{ "force_model", "gravity_n_per_kg", K::NUMBER, 0.0, 100.0, "N/kg", nullptr, {}, "gravity",
			MOVEMENT_FIELD(force_model.gravity_n_per_kg) },
	{ "force_model", "contact_model", K::CHOICE, 0.0, 1.0, "", nullptr, CONTACT_MODEL_NAMES, nullptr,
			MOVEMENT_FIELD(force_model.contact_model) },
	{ "force_model", "friction_engage", K::NUMBER, 0.0, 0.5, "", nullptr, {}, nullptr,
			MOVEMENT_FIELD(force_model.friction_engage) },
	{ "force_model", "contact_stiffness_n", K::NUMBER, 0.0, MAX_GAIN, "N", nullptr, {}, "contact_stiffness",
			MOVEMENT_FIELD(force_model.default_contact.stiffness_n) },
	{ "force_model", "contact_friction_n", K::NUMBER, 0.0, MAX_GAIN, "N", nullptr, {}, "contact_damping",
			MOVEMENT_FIELD(force_model.default_contact.friction_n) },
	{ "smoothing", "enabled", K::FLAG, 0.0, 1.0, "", nullptr, {}, nullptr, MOVEMENT_FIELD(smoothing.enabled) },
	{ "smoothing", "cutoff_hz", K::NUMBER, 0.5, 60.0, "Hz", nullptr, {}, nullptr, MOVEMENT_FIELD(smoothing.cutoff_hz) },
};

#undef MOVEMENT_FIELD

} // namespace

std::span<const ConfigField> movement_config_fields() {
	return FIELDS;
}

} // namespace haptics
