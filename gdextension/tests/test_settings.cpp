// The settings the game hands the servo (servo_settings.schema.toml and each renderer's
// schema): the defaults are within every limit, and every number out of its range (or not
// finite) is refused by its field's name while the previous settings stay.

#include "system/haptics_system.h"
#include "system/settings_validation.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <type_traits>

using namespace haptics;

namespace {

bool mentions(const Status &p_status, const std::string &p_text) {
	return std::strstr(p_status.message(), p_text.c_str()) != nullptr;
}

// Calls p_visit(path, spec, member) for every number of p_value, nested values included.
template <typename T, typename F>
void for_each_number(T &r_value, const std::string &p_path, F &&p_visit) {
	T::visit(r_value, [&](const FieldSpec &p_spec, auto &r_member) {
		using M = std::remove_cvref_t<decltype(r_member)>;
		const std::string path = p_path + "." + p_spec.name;
		if constexpr (SchemaValue<M>) {
			for_each_number(r_member, path, p_visit);
		} else if constexpr (std::is_arithmetic_v<M> && !std::is_same_v<M, bool>) {
			p_visit(path, p_spec, r_member);
		}
	});
}

// Every number of the configuration, one at a time: p_visit(path, spec, member, config).
template <typename F>
void for_each_setting(F &&p_visit) {
	const auto each_of = [&]<typename S>(S RenderConfig::*p_part) {
		size_t count = 0;
		RenderConfig probe;
		for_each_number(probe.*p_part, std::string(), [&](const std::string &, const FieldSpec &, auto &) { ++count; });
		for (size_t index = 0; index < count; ++index) {
			RenderConfig config;
			size_t at = 0;
			for_each_number(config.*p_part, std::string(S::NAME), [&](const std::string &p_path, const FieldSpec &p_spec, auto &r_member) {
				if (at++ == index) {
					p_visit(p_path, p_spec, r_member, config);
				}
			});
		}
	};
	each_of(&RenderConfig::servo);
	each_of(&RenderConfig::movement);
	each_of(&RenderConfig::constraint);
	each_of(&RenderConfig::pong);
}

} // namespace

TEST_CASE("settings: the defaults are within every limit") {
	CHECK(validate_render_config(RenderConfig{}));
	CHECK(check_fields(ServoSettings{}));
	CHECK(check_fields(MovementConfig{}));
	CHECK(check_fields(ConstraintConfig{}));
	CHECK(check_fields(PongConfig{}));
}

TEST_CASE("settings: a number out of range or not finite is refused by name") {
	size_t numbers = 0;
	for_each_setting([&](const std::string &p_path, const FieldSpec &p_spec, auto &r_member, RenderConfig &r_config) {
		using M = std::remove_cvref_t<decltype(r_member)>;
		CAPTURE(p_path);
		++numbers;
		if (std::isfinite(p_spec.max)) {
			r_member = static_cast<M>(p_spec.max * 2.0 + 1.0);
			const Status status = validate_render_config(r_config);
			CHECK(status.code() == StatusCode::OUT_OF_RANGE);
			// The path without the top value's name: what the message names after it.
			CHECK(mentions(status, p_path.substr(p_path.find('.') + 1)));
		}
		if constexpr (std::is_floating_point_v<M>) {
			r_member = std::numeric_limits<M>::quiet_NaN();
			const Status status = validate_render_config(r_config);
			CHECK(status.code() == StatusCode::INVALID_ARGUMENT);
			CHECK(mentions(status, "not finite"));
		}
	});
	CHECK(numbers > 60);
}

TEST_CASE("settings: zero stands for a default where the schema says so, not below the range") {
	RenderConfig config;
	config.servo.safety.slew_rate_n_per_s = 0.0; // No slew limit.
	config.servo.input.input_radius_m = 0.0; // The device's workspace radius.
	CHECK(validate_render_config(config));
	config.servo.safety.slew_rate_n_per_s = 0.5;
	const Status slow = validate_render_config(config);
	CHECK(slow.code() == StatusCode::OUT_OF_RANGE);
	CHECK(mentions(slow, "HapticServoSettings.safety.slew_rate_n_per_s: 0.5 is neither 0 (no slew limit) nor in [1, 1e+06]"));
}

TEST_CASE("settings: a refused configuration leaves the servo's in force") {
	HapticsSystem system;
	RenderConfig config = system.config();
	config.movement.smoothing.cutoff_hz = 1000.0;
	CHECK(mentions(system.configure(config), "HapticMovementSettings.smoothing.cutoff_hz"));
	CHECK(system.config().movement.smoothing.cutoff_hz == SmoothingConfig{}.cutoff_hz);
	config = system.config();
	config.constraint.update = static_cast<ProxyUpdate>(7);
	CHECK(mentions(system.configure(config), "HapticConstraintSettings.update: 7 is none of the 2 values"));
}
