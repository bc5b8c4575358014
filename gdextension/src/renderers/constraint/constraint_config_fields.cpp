#include "renderers/constraint/constraint_renderer.h"

#include "core/config/config_field_access.h"

namespace haptics {

namespace {

#define CONSTRAINT_FIELD(path) HAPTICS_CONFIG_FIELD(ConstraintConfig, path)

using K = FieldKind;

const ConfigField FIELDS[] = {
	{ "constraint", "stiffness_n_per_m", K::NUMBER, 0.0, 5000.0, "N/m", nullptr, {}, "stiffness",
			CONSTRAINT_FIELD(stiffness_n_per_m) },
	{ "constraint", "proxy_radius", K::NUMBER, 1e-6, 1e6, "maze units", nullptr, {}, nullptr,
			CONSTRAINT_FIELD(proxy_radius) },
	{ "constraint", "update", K::CHOICE, 0.0, 1.0, "", nullptr, PROXY_UPDATE_NAMES, nullptr, CONSTRAINT_FIELD(update) },
	{ "constraint", "max_iterations", K::COUNT, 1.0, MAX_PROXY_ITERATIONS, "", nullptr, {}, nullptr,
			CONSTRAINT_FIELD(max_iterations) },
};

#undef CONSTRAINT_FIELD

} // namespace

std::span<const ConfigField> constraint_config_fields() {
	return FIELDS;
}

} // namespace haptics
