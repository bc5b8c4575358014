#include "binding/config_dictionary.h"

#include "binding/dictionary_reader.h"
#include "system/config_table.h"

namespace haptics::binding {

namespace {

const char *kind_name(FieldKind p_kind) {
	switch (p_kind) {
		case FieldKind::NUMBER:
			return "number";
		case FieldKind::COUNT:
			return "count";
		case FieldKind::FLAG:
			return "flag";
		case FieldKind::CHOICE:
			break;
	}
	return "choice";
}

std::string choice_list(const ConfigField &p_field) {
	std::string list;
	for (const char *choice : p_field.choices) {
		list += (list.empty() ? "" : ", ") + std::string(choice);
	}
	return list;
}

// The Variant as the number the table stores, or false with r_error naming the key.
bool to_number(const ConfigField &p_field, const gd::Variant &p_value, const std::string &p_name, double &r_number,
		std::string &r_error) {
	const gd::VariantType type = p_value.get_type();
	if (p_field.kind == FieldKind::FLAG) {
		if (type == gd::VariantType::BOOL) {
			r_number = p_value.as_bool() ? 1.0 : 0.0;
			return true;
		}
		r_error = p_name + ": expected a bool, got " + variant_type_name(type);
		return false;
	}
	if (p_field.kind == FieldKind::CHOICE && (type == gd::VariantType::STRING || type == gd::VariantType::STRING_NAME)) {
		const std::string name = p_value.as_string();
		const int64_t index = name_index(name, p_field.choices);
		if (index < 0) {
			r_error = p_name + " must be one of " + choice_list(p_field) + " (got \"" + name + "\")";
			return false;
		}
		r_number = static_cast<double>(index);
		return true;
	}
	if (type != gd::VariantType::INT && type != gd::VariantType::FLOAT) {
		r_error = p_name + ": expected a number, got " + variant_type_name(type);
		return false;
	}
	r_number = p_value.as_float();
	return true;
}

gd::Variant to_variant(const ConfigField &p_field, double p_number) {
	switch (p_field.kind) {
		case FieldKind::NUMBER:
			return gd::Variant(p_number);
		case FieldKind::FLAG:
			return gd::Variant(p_number != 0.0);
		case FieldKind::COUNT:
		case FieldKind::CHOICE:
			break;
	}
	return gd::Variant(static_cast<int64_t>(p_number));
}

} // namespace

bool apply_config_section(const std::string &p_section, const gd::Dictionary &p_values, RenderConfig &r_config,
		std::string &r_error) {
	const gd::Array keys = p_values.keys();
	for (int64_t i = 0; i < keys.size(); ++i) {
		const gd::Variant key = keys.get(i);
		const std::string name = key.as_string();
		const ConfigField *field = find_config_field(p_section, name);
		if (field == nullptr) {
			std::string known;
			for (const ConfigField &candidate : config_fields()) {
				if (p_section == candidate.section) {
					known += (known.empty() ? "" : ", ") + std::string(candidate.key);
				}
			}
			r_error = p_section + ": unknown setting '" + name + "' (known: " + known + ")";
			return false;
		}
		if (name != field->key) {
			warn_old_key("set_config: " + p_section + "." + name, p_section + "." + field->key);
		}
		gd::Variant value;
		p_values.get(key, value);
		double number = 0.0;
		if (!to_number(*field, value, p_section + "." + name, number, r_error)) {
			return false;
		}
		const Status valid = check_config_value(*field, number);
		if (!valid) {
			r_error = valid.message();
			return false;
		}
		set_config_value(r_config, *field, number);
	}
	return true;
}

gd::Dictionary config_to_dictionary(const RenderConfig &p_config) {
	gd::Dictionary sections;
	for (const char *section : config_sections()) {
		gd::Dictionary values;
		for (const ConfigField &field : config_fields()) {
			if (std::string_view(field.section) == section) {
				values.set(field.key, to_variant(field, config_value(p_config, field)));
			}
		}
		sections.set(section, values.variant());
	}
	return sections;
}

gd::Array config_fields_to_array() {
	const RenderConfig defaults;
	gd::Array out;
	for (const ConfigField &field : config_fields()) {
		gd::Dictionary d;
		d.set("section", field.section);
		d.set("key", field.key);
		d.set("kind", kind_name(field.kind));
		d.set("min", field.min);
		d.set("max", field.max);
		d.set("unit", field.unit);
		d.set("default", to_variant(field, config_value(defaults, field)));
		d.set("zero_means", field.zero_means ? field.zero_means : "");
		gd::Array choices;
		for (const char *choice : field.choices) {
			choices.append(choice);
		}
		d.set("choices", choices.variant());
		d.set("old_key", field.old_key ? field.old_key : "");
		out.append(d.variant());
	}
	return out;
}

} // namespace haptics::binding
