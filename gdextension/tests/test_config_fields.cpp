// The configuration field table: every field once, its default inside its own range, each
// key reachable by its old name, and validation that names the key the game spells.

#include "system/config_table.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <set>
#include <string>

using namespace haptics;

namespace {

bool mentions(const Status &p_status, const std::string &p_text) {
	return std::strstr(p_status.message(), p_text.c_str()) != nullptr;
}

} // namespace

TEST_CASE("config fields: each section and key once, defaults valid, units in the key") {
	std::set<std::string> names;
	std::set<std::string> sections(config_sections().begin(), config_sections().end());
	const RenderConfig defaults;
	for (const ConfigField &field : config_fields()) {
		const std::string name = std::string(field.section) + "." + field.key;
		CAPTURE(name);
		CHECK(names.insert(name).second);
		CHECK(sections.count(field.section) == 1);
		CHECK(check_config_value(field, config_value(defaults, field)));
		CHECK(find_config_field(field.section, field.key) == &field);
		if (field.old_key) {
			CHECK(find_config_field(field.section, field.old_key) == &field);
		}
		const std::string unit = field.unit;
		const std::string key = field.key;
		if (unit == "s" || unit == "Hz" || unit == "m" || unit == "N") {
			std::string suffix = "_" + unit;
			for (char &c : suffix) {
				c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
			}
			CHECK(key.ends_with(suffix));
		}
	}
	CHECK(names.size() == config_fields().size());
	CHECK(find_config_field("safety", "slew_rate")->key == std::string("slew_rate_n_per_s"));
	CHECK(find_config_field("safety", "no_such_key") == nullptr);
	CHECK(find_config_field("smoothing", "slew_rate_n_per_s") == nullptr);
}

TEST_CASE("config fields: a set value reads back, for every field") {
	for (const ConfigField &field : config_fields()) {
		CAPTURE(field.key);
		RenderConfig config;
		const double value = field.kind == FieldKind::FLAG ? 1.0 - config_value(config, field) : field.max;
		set_config_value(config, field, value);
		CHECK(config_value(config, field) == value);
		CHECK(validate_render_config(config));
	}
}

TEST_CASE("config fields: out of range, not finite, wrong kind, each rejected by name") {
	const double nan = std::numeric_limits<double>::quiet_NaN();
	for (const ConfigField &field : config_fields()) {
		const std::string name = std::string(field.section) + "." + field.key;
		CAPTURE(name);
		const Status not_finite = check_config_value(field, nan);
		CHECK(not_finite.code() == StatusCode::INVALID_ARGUMENT);
		CHECK(mentions(not_finite, name));
		if (field.kind == FieldKind::FLAG) {
			CHECK_FALSE(check_config_value(field, 0.5));
			continue; // A bool holds nothing else to reject.
		}
		RenderConfig config;
		set_config_value(config, field, field.kind == FieldKind::CHOICE ? 7.0 : field.max * 2.0 + 1.0);
		const Status rejected = validate_render_config(config);
		CHECK_FALSE(rejected.ok());
		CHECK(mentions(rejected, name));
	}
	const ConfigField &decimation = *find_config_field("telemetry", "decimation");
	CHECK(mentions(check_config_value(decimation, 2.5), "whole number"));
	const ConfigField &slew = *find_config_field("safety", "slew_rate_n_per_s");
	CHECK(check_config_value(slew, 0.0)); // 0 turns the limiter off.
	const Status slow = check_config_value(slew, 0.5);
	CHECK(slow.code() == StatusCode::OUT_OF_RANGE);
	CHECK(mentions(slow, "0 (no slew limit) or in [1, 1e+06]"));
	const ConfigField &update = *find_config_field("constraint", "update");
	CHECK(update.choices.size() == 2);
	CHECK(std::string(update.choices[static_cast<size_t>(ProxyUpdate::FRAME_RATE)]) == "frame");
	const ConfigField &contact_model = *find_config_field("force_model", "contact_model");
	CHECK(contact_model.choices.size() == 2);
	CHECK(std::string(contact_model.choices[static_cast<size_t>(ContactModel::PER_CONTACT)]) == "per_contact");
	CHECK(std::string(contact_model.choices[static_cast<size_t>(ContactModel::PAPER_SUM)]) == "paper_sum");
	CHECK(config_value(RenderConfig{}, contact_model) == 0.0); // per_contact is the default.
}
