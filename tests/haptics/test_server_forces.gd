extends TestSuite
## The movement-based force model through the binding, stepped manually so every number is
## exact: each force is checked against the paper's equation evaluated on the input vector
## the server reports for the same tick. Game axes: x right, y down.

const K := 2.0
const B := 1.5
const TOL := 1e-4

var server: HapticsServer = null


func before_each() -> void:
	server = HapticsServer.new()
	assert_true(server.open_device("simulated"))
	# No ramp, slew or smoothing: the rendered force is the model's force at every tick.
	assert_true(server.set_config("safety", {"startup_ramp_s": 0.0, "slew_rate_n_per_s": 0.0}))
	assert_true(server.set_config("smoothing", {"enabled": false}))
	assert_true(server.set_config("force_model", {"dead_zone": 0.0, "gravity_n_per_kg": 1.0}))


func after_each() -> void:
	server.close_device()


func _push(hand_target_m: Vector2, frame: Dictionary, ticks: int = 200) -> void:
	assert_true(server.set_hand_target(hand_target_m))
	for i: int in ticks:
		assert_true(server.submit_frame(frame))
		assert_true(server.step(0.001))


func _wall(normal: Vector2) -> Dictionary:
	return {"contacts": [{"normal": normal, "stiffness_n": K, "friction_n": B}]}


func _projection(input: Vector2, normal: Vector2) -> Vector2:
	var n: Vector2 = normal.normalized()
	return n * input.dot(n)


func test_pushing_right_into_a_wall_gives_minus_k_p() -> void:
	_push(Vector2(0.06, 0.0), _wall(Vector2.LEFT))
	var i: Vector2 = server.get_input_vector()
	var forces: Dictionary = server.get_forces()
	assert_gt(i.x, 0.1, "the hand pushes the stylus right")
	assert_almost_eq(forces["normal"], -K * _projection(i, Vector2.LEFT), TOL)
	assert_lt(forces["normal"].x, 0.0, "the wall pushes back left")
	assert_almost_eq(forces["total"], forces["normal"] + forces["friction"], TOL)


func test_walls_at_any_angle_push_along_their_own_normal() -> void:
	for degrees: float in [30.0, 45.0, 135.0]:
		server.close_device()
		before_each()
		var normal: Vector2 = Vector2.LEFT.rotated(deg_to_rad(degrees))
		_push(-normal * 0.06, _wall(normal))
		var i: Vector2 = server.get_input_vector()
		var f_n: Vector2 = server.get_forces()["normal"]
		assert_almost_eq(f_n, -K * _projection(i, normal), TOL, "wall at %d°" % degrees)
		assert_almost_eq(absf(f_n.normalized().dot(normal)), 1.0, 1e-3, "along the normal")


func test_sliding_along_the_floor_feels_friction_against_the_tangential_input() -> void:
	var floor_normal: Vector2 = Vector2.UP
	_push(Vector2(0.05, 0.03), _wall(floor_normal))
	var i: Vector2 = server.get_input_vector()
	var r: Vector2 = i - _projection(i, floor_normal)
	var forces: Dictionary = server.get_forces()
	assert_gt(r.x, 0.05)
	assert_almost_eq(forces["friction"], -B * r, TOL)
	assert_lt(forces["friction"].x, 0.0, "friction opposes the sideways push")


func test_a_crate_on_top_is_felt_but_not_one_underneath() -> void:
	var on_top: Dictionary = {"resting": [{"normal": Vector2.DOWN, "mass_kg": 1.2}]}
	_push(Vector2.ZERO, on_top, 5)
	assert_almost_eq(server.get_forces()["weight"], Vector2(0.0, 1.2), TOL)
	var underneath: Dictionary = {"resting": [{"normal": Vector2.UP, "mass_kg": 1.2}]}
	_push(Vector2.ZERO, underneath, 5)
	assert_almost_eq(server.get_forces()["weight"], Vector2.ZERO, TOL)


func test_water_drag_opposes_velocity_and_inertia_points_down() -> void:
	var in_water: Dictionary = {
		"water": {"inside": true, "drag_n_s_per_m": 0.5, "inertia_n": 0.4},
		"velocity_m_per_s": Vector2(1.0, -0.5),
	}
	_push(Vector2.ZERO, in_water, 5)
	var forces: Dictionary = server.get_forces()
	assert_almost_eq(forces["drag"], Vector2(-0.5, 0.25), TOL)
	assert_almost_eq(forces["inertia"], Vector2(0.0, 0.4), TOL)
	_push(Vector2.ZERO, {"velocity_m_per_s": Vector2(1.0, -0.5)}, 5)
	forces = server.get_forces()
	assert_almost_eq(forces["drag"], Vector2.ZERO, TOL, "out of the water")
	assert_almost_eq(forces["inertia"], Vector2.ZERO, TOL)


func test_no_contact_means_no_continuous_force() -> void:
	_push(Vector2(0.07, -0.02), {})
	assert_almost_eq(server.get_forces()["continuous"], Vector2.ZERO, TOL)


func test_an_impact_is_a_raw_decaying_transient() -> void:
	assert_true(server.set_config("smoothing", {"enabled": true}))
	_push(Vector2.ZERO, {}, 5)
	assert_true(
		server.push_impact(
			{
				"direction": Vector2.LEFT,
				"speed_m_per_s": 2.0,
				"gain_n_s_per_m": 0.5,
				"frequency_hz": 100.0,
				"decay_s": 0.02
			}
		)
	)
	var peak: float = 0.0
	var peak_tick: int = -1
	var late: float = 0.0
	for tick: int in 100:
		server.submit_frame({})
		server.step(0.001)
		var impact_force: Vector2 = server.get_forces()["impact"]
		var x: float = absf(impact_force.x)
		if x > peak:
			peak = x
			peak_tick = tick
		if tick >= 90:
			late = maxf(late, x)
	# A = gain * speed = 1 N; the first sine peak comes a quarter period (2.5 ms) in.
	assert_almost_eq(peak, 1.0 * exp(-0.0025 / 0.02), 0.05)
	assert_lt(peak_tick, 6, "the peak comes within the first ticks")
	assert_lt(late, peak * exp(-0.085 / 0.02) * 1.5, "it has decayed")


func test_nan_in_a_frame_is_rejected_and_the_previous_frame_stays() -> void:
	_push(Vector2(0.06, 0.0), _wall(Vector2.LEFT))
	var before: Vector2 = server.get_forces()["normal"]
	expect_error("frame.contacts[0].normal")
	assert_false(server.submit_frame({"contacts": [{"normal": Vector2(NAN, 0.0)}]}))
	server.step(0.001)
	assert_almost_eq(server.get_forces()["normal"], before, 0.01)


func test_a_misspelt_key_is_reported_not_ignored() -> void:
	expect_error("unknown key 'contact'")
	assert_false(server.submit_frame({"contact": []}))


func test_a_wrongly_typed_field_names_itself() -> void:
	expect_error("frame.contacts[0].stiffness: expected a number, got String")
	assert_false(server.submit_frame({"contacts": [{"normal": Vector2.UP, "stiffness": "x"}]}))


func test_bad_settings_are_refused_and_the_old_ones_kept() -> void:
	var cutoff: float = server.get_config()["smoothing"]["cutoff_hz"]
	expect_error("cutoff_hz")
	assert_false(server.set_config("smoothing", {"cutoff_hz": NAN}))
	assert_eq(server.get_config()["smoothing"]["cutoff_hz"], cutoff)
	expect_error("unknown setting 'max_forc'")
	assert_false(server.set_config("safety", {"max_forc": 1.0}))
	expect_error("unknown section 'bogus'")
	assert_false(server.set_config("bogus", {}))


func test_force_output_never_exceeds_the_device_limit() -> void:
	var stiff: Dictionary = {
		"contacts": [{"normal": Vector2.LEFT, "stiffness_n": 90.0, "friction_n": 0.0}]
	}
	_push(Vector2(0.1, 0.0), stiff)
	var limit: float = server.get_device_limits()["max_force_n"]
	assert_almost_eq(limit, 3.3, 1e-6)
	var total: Vector2 = server.get_forces()["total"]
	assert_lt(total.length(), limit + 1e-4)


func test_telemetry_has_one_sample_per_tick_in_the_documented_layout() -> void:
	server.drain_telemetry()
	_push(Vector2(0.06, 0.0), _wall(Vector2.LEFT), 50)
	var stride: int = server.get_telemetry_stride()
	assert_eq(stride, 32)
	assert_eq(server.get_telemetry_columns().size(), stride)
	var samples: PackedFloat32Array = server.drain_telemetry()
	assert_eq(samples.size(), 50 * stride)
	# Telemetry is in device axes (y up): the last total's x matches the game's x.
	var last: int = 49 * stride
	var total_x: int = server.get_telemetry_columns().find("total_x")
	assert_almost_eq(samples[last + total_x], server.get_forces()["total"].x, TOL)
	assert_eq(server.drain_telemetry().size(), 0, "drained")


func test_stepping_refuses_bad_time_steps() -> void:
	expect_error("step")
	assert_false(server.step(0.5))
