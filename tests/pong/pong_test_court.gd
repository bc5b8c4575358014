extends RefCounted
## A court for the unit tests of the pure Pong classes: a configuration written out here,
## so those tests do not depend on the servo's defaults (the scene tests use the servo's).


static func make(overrides: Dictionary = {}) -> PongCourt:
	var config: Dictionary = {
		"court_half_width_m": 1.5,
		"court_half_length_m": 3.0,
		"wall_height_m": 2.5,
		"ball_radius_m": 0.07,
		"paddle_radius_m": 0.22,
		"gravity_m_per_s2": 6.0,
		"restitution_court": 0.85,
		"restitution_wall": 0.9,
		"max_ball_speed_m_per_s": 9.0,
		"workspace_scale": 5.0,
		"beginner_height_m": 0.9,
		"beginner_target_half_width_m": 0.5,
		"restitution_paddle": 0.8,
	}
	config.merge(overrides, true)
	return PongCourt.from_config(config)
