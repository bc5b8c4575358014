extends TestSuite
## The movement-based force model through a door of the test's own, stepped manually so
## every number is exact: each force is checked against the paper's equation evaluated on
## the input vector the door reports for the same tick. Game axes: x right, y down.

const K := 2.0
const B := 1.5
const TOL := 1e-4
const NORMAL := HapticMovementFacts.MovementForce.NORMAL
const FRICTION := HapticMovementFacts.MovementForce.FRICTION
const WEIGHT := HapticMovementFacts.MovementForce.WEIGHT
const DRAG := HapticMovementFacts.MovementForce.DRAG
const INERTIA := HapticMovementFacts.MovementForce.INERTIA

var door: HapticsTestKit.Door = null


func before_each() -> void:
	door = autofree(HapticsTestKit.manual())
	# No ramp, slew or smoothing: the rendered force is the model's force at every tick.
	assert_true(HapticsTestKit.instant(door))
	var settings: HapticMovementSettings = HapticsTestKit.movement(door)
	settings.smoothing.enabled = false
	settings.force_model.gravity_n_per_kg = 1.0
	assert_true(HapticsMovement.of(door).apply_settings(settings))
	assert_true(HapticsTestKit.no_dead_zone(door))


func _push(hand_target_m: Vector2, frame: HapticFrame, ticks: int = 200) -> void:
	assert_true(HapticsTestKit.set_hand_m(door, hand_target_m))
	assert_true(HapticsTestKit.run(door, ticks, frame))


func _wall(normal: Vector2) -> HapticFrame:
	return HapticsTestKit.wall(normal, K, B)


func _part(part: HapticMovementFacts.MovementForce) -> Vector2:
	return HapticsTestKit.movement_part(door, part)


func _projection(input: Vector2, normal: Vector2) -> Vector2:
	var n: Vector2 = normal.normalized()
	return n * input.dot(n)


func test_pushing_right_into_a_wall_gives_minus_k_p() -> void:
	_push(Vector2(0.06, 0.0), _wall(Vector2.LEFT))
	var i: Vector2 = door.get_input_vector()
	var forces: HapticForces = door.get_forces()
	var f_n: Vector2 = forces.parts[NORMAL]
	assert_gt(i.x, 0.1, "the hand pushes the stylus right")
	assert_almost_eq(f_n, -K * _projection(i, Vector2.LEFT), TOL)
	assert_lt(f_n.x, 0.0, "the wall pushes back left")
	assert_almost_eq(forces.total, f_n + forces.parts[FRICTION], TOL)


func test_walls_at_any_angle_push_along_their_own_normal() -> void:
	for degrees: float in [30.0, 45.0, 135.0]:
		before_each()
		var normal: Vector2 = Vector2.LEFT.rotated(deg_to_rad(degrees))
		_push(-normal * 0.06, _wall(normal))
		var i: Vector2 = door.get_input_vector()
		var f_n: Vector2 = _part(NORMAL)
		assert_almost_eq(f_n, -K * _projection(i, normal), TOL, "wall at %d°" % degrees)
		assert_almost_eq(absf(f_n.normalized().dot(normal)), 1.0, 1e-3, "along the normal")


func test_sliding_along_the_floor_feels_friction_against_the_tangential_input() -> void:
	var floor_normal: Vector2 = Vector2.UP
	_push(Vector2(0.05, 0.03), _wall(floor_normal))
	var i: Vector2 = door.get_input_vector()
	var r: Vector2 = i - _projection(i, floor_normal)
	var friction: Vector2 = _part(FRICTION)
	assert_gt(r.x, 0.05)
	assert_almost_eq(friction, -B * r, TOL)
	assert_lt(friction.x, 0.0, "friction opposes the sideways push")


func test_a_crate_on_top_is_felt_but_not_one_underneath() -> void:
	var on_top: HapticFrame = HapticFrame.new()
	on_top.resting = [HapticsTestKit.load(Vector2.DOWN, 1.2)]
	_push(Vector2.ZERO, on_top, 5)
	assert_almost_eq(_part(WEIGHT), Vector2(0.0, 1.2), TOL)
	var underneath: HapticFrame = HapticFrame.new()
	underneath.resting = [HapticsTestKit.load(Vector2.UP, 1.2)]
	_push(Vector2.ZERO, underneath, 5)
	assert_almost_eq(_part(WEIGHT), Vector2.ZERO, TOL)


func test_water_drag_opposes_velocity_and_inertia_points_down() -> void:
	var in_water: HapticFrame = HapticFrame.new()
	in_water.in_water = true
	in_water.water_drag_n_s_per_m = 0.5
	in_water.water_inertia_n = 0.4
	in_water.velocity_m_per_s = Vector2(1.0, -0.5)
	_push(Vector2.ZERO, in_water, 5)
	assert_almost_eq(_part(DRAG), Vector2(-0.5, 0.25), TOL)
	assert_almost_eq(_part(INERTIA), Vector2(0.0, 0.4), TOL)
	var dry: HapticFrame = HapticFrame.new()
	dry.velocity_m_per_s = Vector2(1.0, -0.5)
	_push(Vector2.ZERO, dry, 5)
	assert_almost_eq(_part(DRAG), Vector2.ZERO, TOL, "out of the water")
	assert_almost_eq(_part(INERTIA), Vector2.ZERO, TOL)


func test_no_contact_means_no_continuous_force() -> void:
	_push(Vector2(0.07, -0.02), HapticFrame.new())
	assert_almost_eq(door.get_forces().continuous, Vector2.ZERO, TOL)


func test_an_impact_is_a_raw_decaying_transient() -> void:
	door.smoothing_enabled = true
	_push(Vector2.ZERO, HapticFrame.new(), 5)
	assert_true(door.push_impact(HapticsTestKit.impact(Vector2.LEFT, 2.0, 0.5, 100.0, 0.02)))
	var peak: float = 0.0
	var peak_tick: int = -1
	var late: float = 0.0
	for tick: int in 100:
		door.submit_frame(HapticFrame.new())
		door.servo.step(0.001)
		var x: float = absf(door.get_forces().impact.x)
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
	var before: Vector2 = _part(NORMAL)
	expect_error("submit_frame: HapticFrame.contacts[0].normal: not finite")
	assert_false(door.submit_frame(HapticsTestKit.wall(Vector2(NAN, 0.0))))
	door.servo.step(0.001)
	assert_almost_eq(_part(NORMAL), before, 0.01)


func test_a_contact_without_a_direction_names_itself() -> void:
	expect_error("submit_frame: HapticFrame.contacts[0].normal: zero length: a direction is needed")
	assert_false(door.submit_frame(HapticsTestKit.wall(Vector2.ZERO)))


func test_a_material_out_of_range_names_its_field() -> void:
	expect_error("HapticFrame.contacts[0].material.stiffness_n: 200 is outside [0, 100]")
	assert_false(door.submit_frame(HapticsTestKit.wall(Vector2.UP, 200.0)))
	expect_error("HapticImpact.speed_m_per_s")
	assert_false(door.push_impact(HapticsTestKit.impact(Vector2.UP, -1.0)))


func test_bytes_that_are_no_frame_are_refused_by_name() -> void:
	assert_null(HapticFrame.decode(PackedByteArray([1, 2, 3])))
	assert_has(HapticsWireReader.last_error, "HapticFrame")
	assert_null(HapticFrame.decode(HapticImpact.new().encode()), "another value's bytes")
	assert_has(HapticsWireReader.last_error, "is not this one")
	var bytes: PackedByteArray = _wall(Vector2.LEFT).encode()
	assert_not_null(HapticFrame.decode(bytes), "a frame's own bytes")
	bytes.append(0)
	assert_null(HapticFrame.decode(bytes))
	assert_has(HapticsWireReader.last_error, "1 bytes more than the value holds")


func test_bad_settings_are_refused_and_the_old_ones_kept() -> void:
	var settings: HapticMovementSettings = HapticsTestKit.movement(door)
	var cutoff: float = settings.smoothing.cutoff_hz
	settings.smoothing.cutoff_hz = NAN
	expect_error("HapticMovementSettings.smoothing.cutoff_hz: not finite")
	assert_false(HapticsMovement.of(door).apply_settings(settings))
	assert_eq(HapticsTestKit.movement(door).smoothing.cutoff_hz, cutoff)
	var servo: HapticServoSettings = door.servo.get_settings()
	servo.safety.max_force_n = -1.0
	expect_error("HapticServoSettings.safety.max_force_n")
	assert_false(door.servo.apply_settings(servo))
	assert_eq(door.servo.get_settings().safety.max_force_n, 0.0)


func test_force_output_never_exceeds_the_device_limit() -> void:
	_push(Vector2(0.1, 0.0), HapticsTestKit.wall(Vector2.LEFT, 90.0, 0.0))
	var limit: float = door.device.get_max_force()
	assert_almost_eq(limit, 3.3, 1e-6)
	assert_lt(door.get_forces().total.length(), limit + 1e-4)


func test_telemetry_has_one_sample_per_tick_in_the_documented_layout() -> void:
	var capacity: int = HapticServoConstants.TELEMETRY_QUEUE_CAPACITY
	door.servo.drain_telemetry(capacity)
	_push(Vector2(0.06, 0.0), _wall(Vector2.LEFT), 50)
	var columns: PackedStringArray = door.servo.get_telemetry_columns()
	var stride: int = columns.size()
	assert_eq(stride, 32)
	var samples: PackedFloat32Array = door.servo.drain_telemetry(capacity)
	assert_eq(samples.size(), 50 * stride)
	# Telemetry is in device axes (y up): the last total's x matches the game's x.
	var last: int = 49 * stride
	var total_x: int = columns.find("total_x")
	assert_almost_eq(samples[last + total_x], door.get_forces().total.x, TOL)
	assert_eq(door.servo.drain_telemetry(capacity).size(), 0, "drained")


func test_stepping_refuses_bad_time_steps() -> void:
	expect_error("step")
	assert_false(door.servo.step(0.5))
