#include "core/servo/servo_config_fields.h"

#include "core/config/config_field_access.h"
#include "core/servo/servo_config.h"

namespace haptics {

namespace {

#define SERVO_FIELD(path) HAPTICS_CONFIG_FIELD(ServoConfig, path)

constexpr double MAX_STEP_RATE = 1e6; // Slew rate: above this the limiter does nothing.

using K = FieldKind;

const ConfigField FIELDS[] = {
	{ "force_model", "dead_zone", K::NUMBER, 0.0, 0.5, "", nullptr, {}, nullptr, SERVO_FIELD(input.dead_zone) },
	{ "force_model", "input_radius_m", K::NUMBER, 0.001, 1.0, "m", "the device's workspace radius", {}, "input_radius",
			SERVO_FIELD(input.input_radius_m) },
	{ "force_model", "impact_gain_n_s_per_m", K::NUMBER, 0.0, MAX_GAIN, "N·s/m", nullptr, {}, "impact_gain",
			SERVO_FIELD(default_impact.gain_n_s_per_m) },
	{ "force_model", "impact_frequency_hz", K::NUMBER, MIN_IMPACT_FREQUENCY_HZ, MAX_IMPACT_FREQUENCY_HZ, "Hz", nullptr,
			{}, "impact_frequency", SERVO_FIELD(default_impact.frequency_hz) },
	{ "force_model", "impact_decay_s", K::NUMBER, MIN_IMPACT_DECAY_S, MAX_IMPACT_DECAY_S, "s", nullptr, {},
			"impact_decay", SERVO_FIELD(default_impact.decay_s) },
	{ "safety", "force_scale", K::NUMBER, 0.0, 2.0, "", nullptr, {}, nullptr, SERVO_FIELD(safety.force_scale) },
	{ "safety", "max_force_n", K::NUMBER, 0.0, 100.0, "N", nullptr, {}, "max_force",
			SERVO_FIELD(safety.max_force_n) },
	{ "safety", "max_impact_force_n", K::NUMBER, 0.0, 100.0, "N", nullptr, {}, "max_impact_force",
			SERVO_FIELD(safety.max_impact_force_n) },
	{ "safety", "max_continuous_force_n", K::NUMBER, 0.0, 100.0, "N", "the device's continuous rating", {}, nullptr,
			SERVO_FIELD(safety.max_continuous_force_n) },
	{ "safety", "start_force_n", K::NUMBER, 0.0, 10.0, "N", "no wait", {}, nullptr, SERVO_FIELD(safety.start_force_n) },
	{ "plane_hold", "stiffness_n_per_m", K::NUMBER, 0.0, 5000.0, "N/m", "off", {}, nullptr,
			SERVO_FIELD(plane_hold.stiffness_n_per_m) },
	{ "plane_hold", "damping_n_s_per_m", K::NUMBER, 0.0, 50.0, "N·s/m", nullptr, {}, nullptr,
			SERVO_FIELD(plane_hold.damping_n_s_per_m) },
	{ "safety", "slew_rate_n_per_s", K::NUMBER, 1.0, MAX_STEP_RATE, "N/s", "no slew limit", {}, "slew_rate",
			SERVO_FIELD(safety.slew_rate_n_per_s) },
	{ "safety", "startup_ramp_s", K::NUMBER, 0.0, 5.0, "s", nullptr, {}, "startup_ramp",
			SERVO_FIELD(safety.startup_ramp_s) },
	{ "safety", "watchdog_timeout_s", K::NUMBER, 0.005, 10.0, "s", nullptr, {}, "watchdog_timeout",
			SERVO_FIELD(safety.watchdog_timeout_s) },
	{ "safety", "watchdog_fade_s", K::NUMBER, 0.0, 0.05, "s", nullptr, {}, "watchdog_fade",
			SERVO_FIELD(safety.watchdog_fade_s) },
	{ "telemetry", "enabled", K::FLAG, 0.0, 1.0, "", nullptr, {}, nullptr, SERVO_FIELD(telemetry.enabled) },
	{ "telemetry", "decimation", K::COUNT, 1.0, 1000.0, "", nullptr, {}, nullptr, SERVO_FIELD(telemetry.decimation) },
};

#undef SERVO_FIELD

} // namespace

std::span<const ConfigField> servo_config_fields() {
	return FIELDS;
}

} // namespace haptics
