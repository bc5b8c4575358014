#include "core/config_fields.h"

#include "core/finite_proxy.h"

#include <cmath>
#include <type_traits>

namespace haptics {

namespace {

template <typename T>
T from_number(double p_value) {
	if constexpr (std::is_enum_v<T>) {
		return static_cast<T>(static_cast<std::underlying_type_t<T>>(p_value));
	} else if constexpr (std::is_same_v<T, bool>) {
		return p_value != 0.0;
	} else {
		return static_cast<T>(p_value);
	}
}

template <typename T>
double to_number(T p_value) {
	if constexpr (std::is_enum_v<T>) {
		return static_cast<double>(static_cast<std::underlying_type_t<T>>(p_value));
	} else {
		return static_cast<double>(p_value);
	}
}

// The getter and setter of one member path of RenderConfig.
#define HAPTICS_FIELD(path) \
	[](const RenderConfig &c) { return to_number(c.path); }, \
			[](RenderConfig &c, double v) { c.path = from_number<decltype(c.path)>(v); }

constexpr double MAX_STEP_RATE = 1e6; // Slew rate: above this the limiter does nothing.

using K = FieldKind;

const ConfigField FIELDS[] = {
	{ "force_model", "dead_zone", K::NUMBER, 0.0, 0.5, "", nullptr, {}, nullptr, HAPTICS_FIELD(force_model.dead_zone) },
	{ "force_model", "gravity_n_per_kg", K::NUMBER, 0.0, 100.0, "N/kg", nullptr, {}, "gravity",
			HAPTICS_FIELD(force_model.gravity_n_per_kg) },
	{ "force_model", "input_radius_m", K::NUMBER, 0.001, 1.0, "m", "the device's workspace radius", {}, "input_radius",
			HAPTICS_FIELD(force_model.input_radius_m) },
	{ "force_model", "contact_model", K::CHOICE, 0.0, 1.0, "", nullptr, CONTACT_MODEL_NAMES, nullptr,
			HAPTICS_FIELD(force_model.contact_model) },
	{ "force_model", "friction_engage", K::NUMBER, 0.0, 0.5, "", nullptr, {}, nullptr,
			HAPTICS_FIELD(force_model.friction_engage) },
	{ "force_model", "contact_stiffness_n", K::NUMBER, 0.0, MAX_GAIN, "N", nullptr, {}, "contact_stiffness",
			HAPTICS_FIELD(force_model.default_contact.stiffness) },
	{ "force_model", "contact_friction_n", K::NUMBER, 0.0, MAX_GAIN, "N", nullptr, {}, "contact_damping",
			HAPTICS_FIELD(force_model.default_contact.friction) },
	{ "force_model", "impact_gain_n_s_per_m", K::NUMBER, 0.0, MAX_GAIN, "N·s/m", nullptr, {}, "impact_gain",
			HAPTICS_FIELD(force_model.default_impact.gain) },
	{ "force_model", "impact_frequency_hz", K::NUMBER, MIN_IMPACT_FREQUENCY_HZ, MAX_IMPACT_FREQUENCY_HZ, "Hz", nullptr,
			{}, "impact_frequency", HAPTICS_FIELD(force_model.default_impact.frequency_hz) },
	{ "force_model", "impact_decay_s", K::NUMBER, MIN_IMPACT_DECAY_S, MAX_IMPACT_DECAY_S, "s", nullptr, {},
			"impact_decay", HAPTICS_FIELD(force_model.default_impact.decay_s) },
	{ "smoothing", "enabled", K::FLAG, 0.0, 1.0, "", nullptr, {}, nullptr, HAPTICS_FIELD(smoothing.enabled) },
	{ "smoothing", "cutoff_hz", K::NUMBER, 0.5, 60.0, "Hz", nullptr, {}, nullptr, HAPTICS_FIELD(smoothing.cutoff_hz) },
	{ "safety", "force_scale", K::NUMBER, 0.0, 2.0, "", nullptr, {}, nullptr, HAPTICS_FIELD(safety.force_scale) },
	{ "safety", "max_force_n", K::NUMBER, 0.0, 100.0, "N", nullptr, {}, "max_force",
			HAPTICS_FIELD(safety.max_force_n) },
	{ "safety", "max_impact_force_n", K::NUMBER, 0.0, 100.0, "N", nullptr, {}, "max_impact_force",
			HAPTICS_FIELD(safety.max_impact_force_n) },
	{ "safety", "max_continuous_force_n", K::NUMBER, 0.0, 100.0, "N", "the device's continuous rating", {}, nullptr,
			HAPTICS_FIELD(safety.max_continuous_force_n) },
	{ "safety", "start_force_n", K::NUMBER, 0.0, 10.0, "N", "no wait", {}, nullptr, HAPTICS_FIELD(safety.start_force_n) },
	{ "plane_hold", "stiffness_n_per_m", K::NUMBER, 0.0, 5000.0, "N/m", "off", {}, nullptr,
			HAPTICS_FIELD(plane_hold.stiffness_n_per_m) },
	{ "plane_hold", "damping_n_s_per_m", K::NUMBER, 0.0, 50.0, "N·s/m", nullptr, {}, nullptr,
			HAPTICS_FIELD(plane_hold.damping_n_s_per_m) },
	{ "safety", "slew_rate_n_per_s", K::NUMBER, 1.0, MAX_STEP_RATE, "N/s", "no slew limit", {}, "slew_rate",
			HAPTICS_FIELD(safety.slew_rate_n_per_s) },
	{ "safety", "startup_ramp_s", K::NUMBER, 0.0, 5.0, "s", nullptr, {}, "startup_ramp",
			HAPTICS_FIELD(safety.startup_ramp_s) },
	{ "safety", "watchdog_timeout_s", K::NUMBER, 0.005, 10.0, "s", nullptr, {}, "watchdog_timeout",
			HAPTICS_FIELD(safety.watchdog_timeout_s) },
	{ "safety", "watchdog_fade_s", K::NUMBER, 0.0, 0.05, "s", nullptr, {}, "watchdog_fade",
			HAPTICS_FIELD(safety.watchdog_fade_s) },
	{ "telemetry", "enabled", K::FLAG, 0.0, 1.0, "", nullptr, {}, nullptr, HAPTICS_FIELD(telemetry.enabled) },
	{ "telemetry", "decimation", K::COUNT, 1.0, 1000.0, "", nullptr, {}, nullptr, HAPTICS_FIELD(telemetry.decimation) },
	{ "constraint", "stiffness_n_per_m", K::NUMBER, 0.0, 5000.0, "N/m", nullptr, {}, "stiffness",
			HAPTICS_FIELD(constraint.stiffness_n_per_m) },
	{ "constraint", "proxy_radius", K::NUMBER, 1e-6, 1e6, "maze units", nullptr, {}, nullptr,
			HAPTICS_FIELD(constraint.proxy_radius) },
	{ "constraint", "update", K::CHOICE, 0.0, 1.0, "", nullptr, PROXY_UPDATE_NAMES, nullptr, HAPTICS_FIELD(constraint.update) },
	{ "constraint", "max_iterations", K::COUNT, 1.0, MAX_PROXY_ITERATIONS, "", nullptr, {}, nullptr,
			HAPTICS_FIELD(constraint.max_iterations) },
	// Haptic Battle Pong (pong/pong_config.h says why each default). Cross-field limits
	// (the beginner plane inside the court, a contact spring the servo resolves) are in
	// validate_pong_config.
	{ "pong", "players", K::COUNT, 2.0, 4.0, "", nullptr, {}, nullptr, HAPTICS_FIELD(pong.players) },
	{ "pong", "court_half_width_m", K::NUMBER, 0.5, 20.0, "m", nullptr, {}, nullptr, HAPTICS_FIELD(pong.court_half_width_m) },
	{ "pong", "court_half_length_m", K::NUMBER, 0.5, 50.0, "m", nullptr, {}, nullptr, HAPTICS_FIELD(pong.court_half_length_m) },
	{ "pong", "wall_height_m", K::NUMBER, 0.5, 20.0, "m", nullptr, {}, nullptr, HAPTICS_FIELD(pong.wall_height_m) },
	{ "pong", "workspace_scale", K::NUMBER, 0.1, 100.0, "", nullptr, {}, nullptr, HAPTICS_FIELD(pong.workspace_scale) },
	{ "pong", "paddle_radius_m", K::NUMBER, 0.02, 2.0, "m", nullptr, {}, nullptr, HAPTICS_FIELD(pong.paddle_radius_m) },
	{ "pong", "ball_radius_m", K::NUMBER, 0.01, 0.2, "m", nullptr, {}, nullptr, HAPTICS_FIELD(pong.ball_radius_m) },
	{ "pong", "ball_mass_kg", K::NUMBER, 0.001, 10.0, "kg", nullptr, {}, nullptr, HAPTICS_FIELD(pong.ball_mass_kg) },
	{ "pong", "gravity_m_per_s2", K::NUMBER, 0.0, 30.0, "m/s²", nullptr, {}, nullptr, HAPTICS_FIELD(pong.gravity_m_per_s2) },
	{ "pong", "ball_stiffness_n_per_m", K::NUMBER, 1.0, 3000.0, "N/m", nullptr, {}, nullptr, HAPTICS_FIELD(pong.ball_stiffness_n_per_m) },
	{ "pong", "restitution_paddle", K::NUMBER, 0.0, 1.0, "", nullptr, {}, nullptr, HAPTICS_FIELD(pong.restitution_paddle) },
	{ "pong", "hand_stiffness_n_per_m", K::NUMBER, 0.0, 1000.0, "N/m", nullptr, {}, nullptr, HAPTICS_FIELD(pong.hand_stiffness_n_per_m) },
	{ "pong", "spring_range_m", K::NUMBER, 0.001, 0.2, "m", nullptr, {}, nullptr, HAPTICS_FIELD(pong.spring_range_m) },
	{ "pong", "contact_force_n", K::NUMBER, 0.0, 10.0, "N", nullptr, {}, nullptr, HAPTICS_FIELD(pong.contact_force_n) },
	{ "pong", "restitution_court", K::NUMBER, 0.0, 1.0, "", nullptr, {}, nullptr, HAPTICS_FIELD(pong.restitution_court) },
	{ "pong", "restitution_wall", K::NUMBER, 0.0, 1.0, "", nullptr, {}, nullptr, HAPTICS_FIELD(pong.restitution_wall) },
	{ "pong", "surface_friction", K::NUMBER, 0.0, 2.0, "", nullptr, {}, nullptr, HAPTICS_FIELD(pong.surface_friction) },
	{ "pong", "min_bounce_speed_m_per_s", K::NUMBER, 0.0, 10.0, "m/s", nullptr, {}, nullptr, HAPTICS_FIELD(pong.min_bounce_speed_m_per_s) },
	{ "pong", "spin_gain", K::NUMBER, 0.0, 100000.0, "rad/s² per m·m/s", nullptr, {}, nullptr, HAPTICS_FIELD(pong.spin_gain) },
	{ "pong", "spin_friction_per_s", K::NUMBER, 0.0, 1000.0, "1/s", nullptr, {}, nullptr, HAPTICS_FIELD(pong.spin_friction_per_s) },
	{ "pong", "spin_force_gain", K::NUMBER, 0.0, 10.0, "N per rad/s·m", nullptr, {}, nullptr, HAPTICS_FIELD(pong.spin_force_gain) },
	{ "pong", "max_spin_rad_per_s", K::NUMBER, 0.0, 1000.0, "rad/s", nullptr, {}, nullptr, HAPTICS_FIELD(pong.max_spin_rad_per_s) },
	{ "pong", "air_linear_decel_m_per_s2", K::NUMBER, 0.0, 20.0, "m/s²", nullptr, {}, nullptr, HAPTICS_FIELD(pong.air_linear_decel_m_per_s2) },
	{ "pong", "air_angular_decel_rad_per_s2", K::NUMBER, 0.0, 500.0, "rad/s²", nullptr, {}, nullptr, HAPTICS_FIELD(pong.air_angular_decel_rad_per_s2) },
	{ "pong", "max_ball_speed_m_per_s", K::NUMBER, 0.5, 50.0, "m/s", nullptr, {}, nullptr, HAPTICS_FIELD(pong.max_ball_speed_m_per_s) },
	{ "pong", "recoil_force_n", K::NUMBER, 0.0, 10.0, "N", nullptr, {}, nullptr, HAPTICS_FIELD(pong.recoil_force_n) },
	{ "pong", "recoil_duration_s", K::NUMBER, 0.001, 2.0, "s", nullptr, {}, nullptr, HAPTICS_FIELD(pong.recoil_duration_s) },
	{ "pong", "hit_force_n", K::NUMBER, 0.0, 10.0, "N", nullptr, {}, nullptr, HAPTICS_FIELD(pong.hit_force_n) },
	{ "pong", "hit_duration_s", K::NUMBER, 0.001, 2.0, "s", nullptr, {}, nullptr, HAPTICS_FIELD(pong.hit_duration_s) },
	{ "pong", "mine_effect_duration_s", K::NUMBER, 0.01, 60.0, "s", nullptr, {}, nullptr, HAPTICS_FIELD(pong.mine_effect_duration_s) },
	{ "pong", "mine_effect_ramp_s", K::NUMBER, 0.0, 5.0, "s", nullptr, {}, nullptr, HAPTICS_FIELD(pong.mine_effect_ramp_s) },
	{ "pong", "slow_damping_n_s_per_m", K::NUMBER, 0.0, 10.0, "N·s/m", nullptr, {}, nullptr, HAPTICS_FIELD(pong.slow_damping_n_s_per_m) },
	{ "pong", "heavy_force_n", K::NUMBER, 0.0, 10.0, "N", nullptr, {}, nullptr, HAPTICS_FIELD(pong.heavy_force_n) },
	{ "pong", "remote_stiffness_n_per_m", K::NUMBER, 0.0, 1000.0, "N/m", nullptr, {}, nullptr, HAPTICS_FIELD(pong.remote_stiffness_n_per_m) },
	{ "pong", "remote_cutoff_hz", K::NUMBER, 0.1, 100.0, "Hz", nullptr, {}, nullptr, HAPTICS_FIELD(pong.remote_cutoff_hz) },
	{ "pong", "remote_max_force_n", K::NUMBER, 0.0, 10.0, "N", nullptr, {}, nullptr, HAPTICS_FIELD(pong.remote_max_force_n) },
	{ "pong", "remote_max_extrapolation_s", K::NUMBER, 0.0, 1.0, "s", nullptr, {}, nullptr, HAPTICS_FIELD(pong.remote_max_extrapolation_s) },
	{ "pong", "remote_passivity", K::FLAG, 0.0, 1.0, "", nullptr, {}, nullptr, HAPTICS_FIELD(pong.remote_passivity) },
	{ "pong", "beginner_height_m", K::NUMBER, 0.05, 2.0, "m", nullptr, {}, nullptr, HAPTICS_FIELD(pong.beginner_height_m) },
	{ "pong", "beginner_target_half_width_m", K::NUMBER, 0.05, 1.5, "m", nullptr, {}, nullptr, HAPTICS_FIELD(pong.beginner_target_half_width_m) },
};

#undef HAPTICS_FIELD

constexpr const char *SECTIONS[] = { "force_model", "smoothing", "safety", "plane_hold", "telemetry", "constraint",
	"pong" };

} // namespace

std::span<const ConfigField> config_fields() {
	return FIELDS;
}

std::span<const char *const> config_sections() {
	return SECTIONS;
}

const ConfigField *find_config_field(std::string_view p_section, std::string_view p_key) {
	for (const ConfigField &field : FIELDS) {
		if (p_section == field.section && (p_key == field.key || (field.old_key && p_key == field.old_key))) {
			return &field;
		}
	}
	return nullptr;
}

Status check_config_value(const ConfigField &p_field, double p_value) {
	const char *section = p_field.section;
	const char *key = p_field.key;
	if (!std::isfinite(p_value)) {
		return Status::error(StatusCode::INVALID_ARGUMENT, "%s.%s: not finite (%g)", section, key, p_value);
	}
	switch (p_field.kind) {
		case FieldKind::NUMBER:
			if (p_field.zero_means && p_value == 0.0) {
				return Status::success();
			}
			break;
		case FieldKind::COUNT:
			if (p_value != std::floor(p_value)) {
				return Status::error(StatusCode::INVALID_ARGUMENT, "%s.%s must be a whole number (got %g)", section, key,
						p_value);
			}
			break;
		case FieldKind::FLAG:
			if (p_value != 0.0 && p_value != 1.0) {
				return Status::error(StatusCode::INVALID_ARGUMENT, "%s.%s must be true or false (got %g)", section, key,
						p_value);
			}
			return Status::success();
		case FieldKind::CHOICE:
			if (p_value != std::floor(p_value) || p_value < 0.0 || p_value >= static_cast<double>(p_field.choices.size())) {
				return Status::error(StatusCode::INVALID_ARGUMENT, "%s.%s: unknown value %g", section, key, p_value);
			}
			return Status::success();
	}
	if (p_value < p_field.min || p_value > p_field.max) {
		if (p_field.zero_means) {
			return Status::error(StatusCode::OUT_OF_RANGE, "%s.%s must be 0 (%s) or in [%g, %g] (got %g)", section, key,
					p_field.zero_means, p_field.min, p_field.max, p_value);
		}
		return Status::error(StatusCode::OUT_OF_RANGE, "%s.%s must be in [%g, %g] (got %g)", section, key, p_field.min,
				p_field.max, p_value);
	}
	return Status::success();
}

} // namespace haptics
