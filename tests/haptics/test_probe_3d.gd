extends TestSuite
## The 3D probe on both body kinds a game uses, a CharacterBody3D ([Explorer]) and a
## RigidBody3D ([Roller3D]), on every stage of the issue: floor, wall, ramp, corner, ceiling,
## a crate on top, water and a moving platform. A door of the test's own is stepped at 1 kHz
## of device time for every 60 Hz physics frame; the simulated hand moves the stylus in 3D
## and the forces are read back in view axes (no camera: the world's own).

## Runs scenes for seconds: make check (--quick) leaves it out.
const SLOW := true

const K := 2.0
const B := 1.0
const TICKS_PER_FRAME := 17
const REACH_M := 0.1
const NORMAL := HapticMovementFacts.MovementForce.NORMAL
const FRICTION := HapticMovementFacts.MovementForce.FRICTION
const WEIGHT := HapticMovementFacts.MovementForce.WEIGHT
const DRAG := HapticMovementFacts.MovementForce.DRAG
const INERTIA := HapticMovementFacts.MovementForce.INERTIA
const KINDS: Array[String] = ["character", "rigid"]

var door: HapticsTestKit.Door = null
var stage: Stage3D = null


func before_each() -> void:
	door = autofree(HapticsTestKit.manual())
	assert_true(HapticsTestKit.no_ramp(door) and HapticsTestKit.no_dead_zone(door))


func after_each() -> void:
	if is_instance_valid(stage):
		stage.free()


func _new_stage() -> void:
	if is_instance_valid(stage):
		stage.free()
	stage = Stage3D.new()
	add_child(stage)


func _body(kind: String, at: Vector3) -> PhysicsBody3D:
	if kind == "character":
		return stage.walker(door, at)
	return stage.roller(door, at)


func _run_frames(count: int) -> void:
	for i: int in count:
		await get_tree().physics_frame
		HapticsTestKit.run(door, TICKS_PER_FRAME)


# The hand at [param normalised] of the workspace, device axes (x right, y up, z toward you).
func _hand(normalised: Vector3) -> void:
	assert_true(door.device.set_hand_target_3d(normalised * REACH_M))


func _part(part: HapticMovementFacts.MovementForce) -> Vector3:
	return door.get_forces_3d().parts[part]


# The one-sided constraint's answer to [param i] at a surface of normal [param n] alone:
# k max(0, -i.n) n (docs/probe-3d.md).
func _pushed_back(i: Vector3, n: Vector3) -> Vector3:
	return n * K * maxf(0.0, -i.dot(n))


func _normals(body: PhysicsBody3D) -> Array[Vector3]:
	var out: Array[Vector3] = []
	for contact: HapticContact3D in Stage3D.probe_of(body).last_frame.contacts:
		out.append(contact.normal)
	return out


func _has_normal(body: PhysicsBody3D, normal: Vector3, tolerance: float = 0.02) -> bool:
	for seen: Vector3 in _normals(body):
		if seen.distance_to(normal) < tolerance:
			return true
	return false


func test_pressing_the_floor_is_answered_upward_with_k_times_the_press() -> void:
	for kind: String in KINDS:
		_new_stage()
		var body: PhysicsBody3D = _body(kind, Vector3(0.0, Stage3D.RADIUS, 0.0))
		_hand(Vector3(0.0, -0.5, 0.0))
		await _run_frames(30)
		assert_true(_has_normal(body, Vector3.UP), "%s: the floor, normal up" % kind)
		# The simulated hand gives a little under the push, so i is measured, not assumed.
		var i: Vector3 = door.get_input_vector_3d()
		assert_almost_eq(i, Vector3(0.0, -0.5, 0.0), 0.05, "%s: pressing down" % kind)
		assert_almost_eq(_part(NORMAL), _pushed_back(i, Vector3.UP), 1e-3, kind)
		assert_true(door.game_3d, "a 3D frame makes the door 3D")


func test_walking_into_a_wall_in_front_is_pushed_back_toward_the_player() -> void:
	for kind: String in KINDS:
		_new_stage()
		stage.box(Vector3(6.0, 2.0, 0.5), Vector3(0.0, 1.0, -2.25))
		var body: PhysicsBody3D = _body(kind, Vector3(0.0, Stage3D.RADIUS, 0.0))
		_hand(Vector3(0.0, 0.0, -0.5))
		await _run_frames(120)
		assert_almost_eq(body.position.z, -2.0 + Stage3D.RADIUS, 0.05, "%s at the wall" % kind)
		assert_true(_has_normal(body, Vector3.BACK), "%s: the wall's normal, toward us" % kind)
		assert_almost_eq(
			_part(NORMAL), _pushed_back(door.get_input_vector_3d(), Vector3.BACK), 1e-3
		)
		assert_gt(_part(NORMAL).z, 0.8, "%s: about k times half the reach" % kind)


func test_a_corner_of_two_walls_pushes_back_each_walls_part() -> void:
	for kind: String in KINDS:
		_new_stage()
		stage.box(Vector3(6.0, 2.0, 0.5), Vector3(0.0, 1.0, -2.25))
		stage.box(Vector3(0.5, 2.0, 6.0), Vector3(-2.25, 1.0, 0.0))
		var body: PhysicsBody3D = _body(kind, Vector3(0.0, Stage3D.RADIUS, 0.0))
		_hand(Vector3(-0.4, 0.0, -0.4))
		await _run_frames(150)
		assert_true(_has_normal(body, Vector3.BACK), "%s: the wall in front" % kind)
		assert_true(_has_normal(body, Vector3.RIGHT), "%s: the wall on the left" % kind)
		var i: Vector3 = door.get_input_vector_3d()
		var both: Vector3 = _pushed_back(i, Vector3.BACK) + _pushed_back(i, Vector3.RIGHT)
		assert_almost_eq(_part(NORMAL), both, 1e-3, kind)
		assert_gt(minf(_part(NORMAL).x, _part(NORMAL).z), 0.6, "%s: both walls push" % kind)
		assert_almost_eq(_part(FRICTION), Vector3.ZERO, 0.03, "%s: no slide" % kind)


func test_standing_on_a_ramp_the_press_is_answered_along_the_ramps_normal() -> void:
	var tilt: float = deg_to_rad(20.0)
	# Turned about x by +20°: the ramp's top faces up and toward the viewer.
	var normal: Vector3 = Vector3(0.0, cos(tilt), sin(tilt))
	for kind: String in KINDS:
		_new_stage()
		stage.box(Vector3(4.0, 0.5, 6.0), Vector3(0.0, 0.5, 0.0), Vector3(20.0, 0.0, 0.0))
		var body: PhysicsBody3D = _body(kind, Vector3(0.0, 1.4, 0.0))
		if body is RigidBody3D:
			(body as RigidBody3D).freeze_mode = RigidBody3D.FREEZE_MODE_STATIC
		_hand(Vector3(0.0, -0.5, 0.0))
		await _run_frames(20)
		if body is RigidBody3D:
			# A ball would roll off: held where it landed, its contact stays.
			(body as RigidBody3D).freeze = true
		await _run_frames(10)
		assert_true(_has_normal(body, normal, 0.03), "%s: the ramp's normal %s" % [kind, normal])
		var f_n: Vector3 = _part(NORMAL)
		assert_almost_eq(f_n, _pushed_back(door.get_input_vector_3d(), normal), 0.01, kind)
		assert_almost_eq(f_n.normalized(), normal, 0.03, "%s: along the ramp's normal" % kind)


func test_pushing_up_into_a_ceiling_is_pushed_down() -> void:
	for kind: String in KINDS:
		_new_stage()
		stage.box(Vector3(6.0, 0.5, 6.0), Vector3(0.0, 2.0 * Stage3D.RADIUS + 0.3, 0.0))
		var body: PhysicsBody3D = _body(kind, Vector3(0.0, Stage3D.RADIUS, 0.0))
		if body is RigidBody3D:
			(body as RigidBody3D).gravity_scale = -1.0  # A balloon: it rises to the ceiling.
		_hand(Vector3(0.0, 0.8, 0.0))
		var at_ceiling: int = 0
		for frame: int in 60:
			await _run_frames(1)
			if _has_normal(body, Vector3.DOWN):
				at_ceiling += 1
				var i: Vector3 = door.get_input_vector_3d()
				assert_almost_eq(_part(NORMAL), _pushed_back(i, Vector3.DOWN), 0.01, kind)
				assert_lt(_part(NORMAL).y, -1.0, "%s: pushed down about k i" % kind)
		assert_gt(at_ceiling, 0, "%s reached the ceiling" % kind)


func test_a_crate_on_top_weighs_on_the_hand_and_one_beside_does_not() -> void:
	for kind: String in KINDS:
		_new_stage()
		var body: PhysicsBody3D = _body(kind, Vector3(0.0, Stage3D.RADIUS, 0.0))
		stage.crate(3.0, 0.4, Vector3(2.0, 0.2, 0.0))
		if body is RigidBody3D:
			(body as RigidBody3D).lock_rotation = true
		await _run_frames(20)
		assert_almost_eq(_part(WEIGHT), Vector3.ZERO, 1e-6, "%s: beside" % kind)
		var on_top: RigidBody3D = stage.crate(
			2.0, 0.3, Vector3(0.0, 2.0 * Stage3D.RADIUS + 0.2, 0.0)
		)
		await _run_frames(40)
		assert_true(on_top.position.y > Stage3D.RADIUS, "%s: the crate rests on the body" % kind)
		var gravity: float = HapticsTestKit.movement(door).force_model.gravity_n_per_kg
		assert_almost_eq(_part(WEIGHT), Vector3(0.0, -2.0 * gravity, 0.0), 0.05, kind)


func test_water_drags_against_the_3d_velocity_and_pulls_down() -> void:
	for kind: String in KINDS:
		_new_stage()
		var water: HapticWater3D = stage.water(Vector3(8.0, 2.0, 8.0), Vector3(0.0, 1.0, 0.0))
		water.density = 0.0  # No buoyancy: the ball stays on the bottom.
		var body: PhysicsBody3D = _body(kind, Vector3(0.0, Stage3D.RADIUS, 0.0))
		_hand(Vector3(0.5, 0.0, -0.5))
		await _run_frames(40)
		var frame: HapticFrame3D = Stage3D.probe_of(body).last_frame
		assert_true(frame.in_water, "%s: in the water" % kind)
		var velocity: Vector3 = frame.velocity_m_per_s
		assert_gt(velocity.length(), 0.3, "%s moves" % kind)
		assert_almost_eq(_part(DRAG), -0.8 * velocity, 1e-3, kind)
		assert_almost_eq(_part(INERTIA), Vector3(0.0, -0.4, 0.0), 1e-6, kind)


func test_landing_is_one_impact_at_the_fall_speed_and_a_moving_platform_adds_none() -> void:
	for kind: String in KINDS:
		_new_stage()
		var platform: AnimatableBody3D = stage.platform(Vector3(0.0, 0.1, 0.0))
		var body: PhysicsBody3D = _body(kind, Vector3(0.0, 1.2 + Stage3D.RADIUS, 0.0))
		if body is RigidBody3D:
			(body as RigidBody3D).lock_rotation = true
		var speeds: Array[float] = []
		Stage3D.probe_of(body).impact.connect(
			func(_collider: Object, _normal: Vector3, speed: float) -> void: speeds.append(speed)
		)
		await _run_frames(40)
		# Fallen 1 m: v = sqrt(2 g h), about 4.4 m/s.
		assert_eq(speeds.size(), 1, "%s: one landing, %s" % [kind, speeds])
		if not speeds.is_empty():
			assert_almost_eq(speeds[0], sqrt(2.0 * 9.8 * 1.0), 0.5, "%s: the fall speed" % kind)
		for i: int in 90:
			platform.position.x = 0.6 * sin(i / 30.0)
			await _run_frames(1)
		assert_eq(speeds.size(), 1, "%s: riding the platform rings nothing: %s" % [kind, speeds])
		assert_true(_has_normal(body, Vector3.UP), "%s still stands on it" % kind)
