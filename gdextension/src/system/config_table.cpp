#include "system/config_table.h"

#include "core/servo/servo_config_fields.h"

#include <cstddef>
#include <cstring>
#include <vector>

namespace haptics {

namespace {

// Whose rows they are, and where its settings are in a RenderConfig.
struct Owner {
	std::span<const ConfigField> rows;
	const void *(*part)(const RenderConfig &p_config);
};

// Built on first use, on the game thread: the rows copied into one array (what
// config_fields() hands out), each with its owner.
struct Table {
	std::vector<ConfigField> fields;
	std::vector<const Owner *> owners; // Parallel to fields.
	std::vector<const char *> sections;
};

const Table &table() {
	static const Owner OWNERS[] = {
		{ servo_config_fields(), [](const RenderConfig &p_config) -> const void * { return &p_config.servo; } },
#define HAPTICS_OWNER_OF(MODE, name, Class) \
	{ Class::info().config_fields, [](const RenderConfig &p_config) -> const void * { return &p_config.name; } },
		HAPTICS_RENDERERS(HAPTICS_OWNER_OF)
#undef HAPTICS_OWNER_OF
	};
	static const Table TABLE = [] {
		Table built;
		for (const Owner &owner : OWNERS) {
			for (const ConfigField &row : owner.rows) {
				built.fields.push_back(row);
				built.owners.push_back(&owner);
				bool known = false;
				for (const char *section : built.sections) {
					known = known || std::strcmp(section, row.section) == 0;
				}
				if (!known) {
					built.sections.push_back(row.section);
				}
			}
		}
		return built;
	}();
	return TABLE;
}

const Owner &owner_of(const ConfigField &p_field) {
	const Table &rows = table();
	return *rows.owners[static_cast<size_t>(&p_field - rows.fields.data())];
}

// Status::success() for a renderer without joint limits.
template <typename R>
Status validate_settings(const typename R::Config &p_config) {
	if constexpr (requires { R::validate(p_config); }) {
		return R::validate(p_config);
	} else {
		return Status::success();
	}
}

} // namespace

std::span<const ConfigField> config_fields() {
	return table().fields;
}

std::span<const char *const> config_sections() {
	return table().sections;
}

const ConfigField *find_config_field(std::string_view p_section, std::string_view p_key) {
	for (const ConfigField &field : config_fields()) {
		if (p_section == field.section && (p_key == field.key || (field.old_key && p_key == field.old_key))) {
			return &field;
		}
	}
	return nullptr;
}

double config_value(const RenderConfig &p_config, const ConfigField &p_field) {
	return p_field.get(owner_of(p_field).part(p_config));
}

void set_config_value(RenderConfig &r_config, const ConfigField &p_field, double p_value) {
	// r_config is not const, so neither is the part of it the owner points at.
	p_field.set(const_cast<void *>(owner_of(p_field).part(r_config)), p_value);
}

Status validate_render_config(const RenderConfig &p_config) {
	for (const ConfigField &field : config_fields()) {
		HAPTICS_RETURN_IF_ERROR(check_config_value(field, config_value(p_config, field)));
	}
#define HAPTICS_VALIDATE_OF(MODE, name, Class) HAPTICS_RETURN_IF_ERROR(validate_settings<Class>(p_config.name));
	HAPTICS_RENDERERS(HAPTICS_VALIDATE_OF)
#undef HAPTICS_VALIDATE_OF
	const int32_t mode = p_config.servo.render_mode;
	if (mode < 0 || static_cast<size_t>(mode) >= RENDER_MODE_COUNT) {
		return Status::error(StatusCode::INVALID_ARGUMENT, "render_mode: unknown mode %d", static_cast<int>(mode));
	}
	return Status::success();
}

} // namespace haptics
