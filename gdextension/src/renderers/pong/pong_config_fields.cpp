#include "renderers/pong/pong_renderer.h"

#include "core/config/config_field_access.h"

namespace haptics {

namespace {

#define PONG_FIELD(path) HAPTICS_CONFIG_FIELD(PongConfig, path)

using K = FieldKind;

// pong_config.h says why each default. Limits that join fields (the beginner plane inside
// the court, a contact spring the servo resolves) are in validate_pong_config.
const ConfigField FIELDS[] = {
	{ "pong", "players", K::COUNT, 2.0, 4.0, "", nullptr, {}, nullptr, PONG_FIELD(players) },
	{ "pong", "court_half_width_m", K::NUMBER, 0.5, 20.0, "m", nullptr, {}, nullptr, PONG_FIELD(court_half_width_m) },
	{ "pong", "court_half_length_m", K::NUMBER, 0.5, 50.0, "m", nullptr, {}, nullptr, PONG_FIELD(court_half_length_m) },
	{ "pong", "wall_height_m", K::NUMBER, 0.5, 20.0, "m", nullptr, {}, nullptr, PONG_FIELD(wall_height_m) },
	{ "pong", "workspace_scale", K::NUMBER, 0.1, 100.0, "", nullptr, {}, nullptr, PONG_FIELD(workspace_scale) },
	{ "pong", "paddle_radius_m", K::NUMBER, 0.02, 2.0, "m", nullptr, {}, nullptr, PONG_FIELD(paddle_radius_m) },
	{ "pong", "ball_radius_m", K::NUMBER, 0.01, 0.2, "m", nullptr, {}, nullptr, PONG_FIELD(ball_radius_m) },
	{ "pong", "ball_mass_kg", K::NUMBER, 0.001, 10.0, "kg", nullptr, {}, nullptr, PONG_FIELD(ball_mass_kg) },
	{ "pong", "gravity_m_per_s2", K::NUMBER, 0.0, 30.0, "m/s²", nullptr, {}, nullptr, PONG_FIELD(gravity_m_per_s2) },
	{ "pong", "ball_stiffness_n_per_m", K::NUMBER, 1.0, 3000.0, "N/m", nullptr, {}, nullptr, PONG_FIELD(ball_stiffness_n_per_m) },
	{ "pong", "restitution_paddle", K::NUMBER, 0.0, 1.0, "", nullptr, {}, nullptr, PONG_FIELD(restitution_paddle) },
	{ "pong", "hand_stiffness_n_per_m", K::NUMBER, 0.0, 1000.0, "N/m", nullptr, {}, nullptr, PONG_FIELD(hand_stiffness_n_per_m) },
	{ "pong", "spring_range_m", K::NUMBER, 0.001, 0.2, "m", nullptr, {}, nullptr, PONG_FIELD(spring_range_m) },
	{ "pong", "contact_force_n", K::NUMBER, 0.0, 10.0, "N", nullptr, {}, nullptr, PONG_FIELD(contact_force_n) },
	{ "pong", "restitution_court", K::NUMBER, 0.0, 1.0, "", nullptr, {}, nullptr, PONG_FIELD(restitution_court) },
	{ "pong", "restitution_wall", K::NUMBER, 0.0, 1.0, "", nullptr, {}, nullptr, PONG_FIELD(restitution_wall) },
	{ "pong", "surface_friction", K::NUMBER, 0.0, 2.0, "", nullptr, {}, nullptr, PONG_FIELD(surface_friction) },
	{ "pong", "min_bounce_speed_m_per_s", K::NUMBER, 0.0, 10.0, "m/s", nullptr, {}, nullptr, PONG_FIELD(min_bounce_speed_m_per_s) },
	{ "pong", "spin_gain", K::NUMBER, 0.0, 100000.0, "rad/s² per m·m/s", nullptr, {}, nullptr, PONG_FIELD(spin_gain) },
	{ "pong", "spin_friction_per_s", K::NUMBER, 0.0, 1000.0, "1/s", nullptr, {}, nullptr, PONG_FIELD(spin_friction_per_s) },
	{ "pong", "spin_force_gain", K::NUMBER, 0.0, 10.0, "N per rad/s·m", nullptr, {}, nullptr, PONG_FIELD(spin_force_gain) },
	{ "pong", "max_spin_rad_per_s", K::NUMBER, 0.0, 1000.0, "rad/s", nullptr, {}, nullptr, PONG_FIELD(max_spin_rad_per_s) },
	{ "pong", "air_linear_decel_m_per_s2", K::NUMBER, 0.0, 20.0, "m/s²", nullptr, {}, nullptr, PONG_FIELD(air_linear_decel_m_per_s2) },
	{ "pong", "air_angular_decel_rad_per_s2", K::NUMBER, 0.0, 500.0, "rad/s²", nullptr, {}, nullptr, PONG_FIELD(air_angular_decel_rad_per_s2) },
	{ "pong", "max_ball_speed_m_per_s", K::NUMBER, 0.5, 50.0, "m/s", nullptr, {}, nullptr, PONG_FIELD(max_ball_speed_m_per_s) },
	{ "pong", "recoil_force_n", K::NUMBER, 0.0, 10.0, "N", nullptr, {}, nullptr, PONG_FIELD(recoil_force_n) },
	{ "pong", "recoil_duration_s", K::NUMBER, 0.001, 2.0, "s", nullptr, {}, nullptr, PONG_FIELD(recoil_duration_s) },
	{ "pong", "hit_force_n", K::NUMBER, 0.0, 10.0, "N", nullptr, {}, nullptr, PONG_FIELD(hit_force_n) },
	{ "pong", "hit_duration_s", K::NUMBER, 0.001, 2.0, "s", nullptr, {}, nullptr, PONG_FIELD(hit_duration_s) },
	{ "pong", "mine_effect_duration_s", K::NUMBER, 0.01, 60.0, "s", nullptr, {}, nullptr, PONG_FIELD(mine_effect_duration_s) },
	{ "pong", "mine_effect_ramp_s", K::NUMBER, 0.0, 5.0, "s", nullptr, {}, nullptr, PONG_FIELD(mine_effect_ramp_s) },
	{ "pong", "slow_damping_n_s_per_m", K::NUMBER, 0.0, 10.0, "N·s/m", nullptr, {}, nullptr, PONG_FIELD(slow_damping_n_s_per_m) },
	{ "pong", "heavy_force_n", K::NUMBER, 0.0, 10.0, "N", nullptr, {}, nullptr, PONG_FIELD(heavy_force_n) },
	{ "pong", "remote_stiffness_n_per_m", K::NUMBER, 0.0, 1000.0, "N/m", nullptr, {}, nullptr, PONG_FIELD(remote_stiffness_n_per_m) },
	{ "pong", "remote_cutoff_hz", K::NUMBER, 0.1, 100.0, "Hz", nullptr, {}, nullptr, PONG_FIELD(remote_cutoff_hz) },
	{ "pong", "remote_max_force_n", K::NUMBER, 0.0, 10.0, "N", nullptr, {}, nullptr, PONG_FIELD(remote_max_force_n) },
	{ "pong", "remote_max_extrapolation_s", K::NUMBER, 0.0, 1.0, "s", nullptr, {}, nullptr, PONG_FIELD(remote_max_extrapolation_s) },
	{ "pong", "remote_passivity", K::FLAG, 0.0, 1.0, "", nullptr, {}, nullptr, PONG_FIELD(remote_passivity) },
	{ "pong", "correction_time_constant_s", K::NUMBER, 0.001, 1.0, "s", nullptr, {}, nullptr, PONG_FIELD(correction_time_constant_s) },
	{ "pong", "correction_max_speed_m_per_s", K::NUMBER, 0.1, 50.0, "m/s", nullptr, {}, nullptr, PONG_FIELD(correction_max_speed_m_per_s) },
	{ "pong", "correction_force_rate_n_per_s", K::NUMBER, 1.0, 1e6, "N/s", nullptr, {}, nullptr, PONG_FIELD(correction_force_rate_n_per_s) },
	{ "pong", "beginner_height_m", K::NUMBER, 0.05, 2.0, "m", nullptr, {}, nullptr, PONG_FIELD(beginner_height_m) },
	{ "pong", "beginner_target_half_width_m", K::NUMBER, 0.05, 1.5, "m", nullptr, {}, nullptr, PONG_FIELD(beginner_target_half_width_m) },

};

#undef PONG_FIELD

} // namespace

std::span<const ConfigField> pong_config_fields() {
	return FIELDS;
}

} // namespace haptics
