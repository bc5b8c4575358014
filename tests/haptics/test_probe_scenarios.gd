extends TestSuite
## The haptic probe on a real body in a real physics world, with a door of the test's own
## stepped at 1 kHz of device time for every 50 Hz physics frame. The simulated hand moves
## the stylus; the probe turns the stylus into the player's input and the contacts into
## forces.

## Runs scenes or processes for seconds: make check (--quick) leaves it out.
const SLOW := true

const TEST_ROOM := preload("res://tests/support/room.tscn")
const K := 2.0
const B := 1.0
const TICKS_PER_FRAME := 20
const NORMAL := HapticMovementFacts.MovementForce.NORMAL
const FRICTION := HapticMovementFacts.MovementForce.FRICTION
const WEIGHT := HapticMovementFacts.MovementForce.WEIGHT
const DRAG := HapticMovementFacts.MovementForce.DRAG
const INERTIA := HapticMovementFacts.MovementForce.INERTIA

var door: HapticsTestKit.Door = null
var room: TestRoom = null
var player: Player = null
var probe: HapticProbe = null


func before_each() -> void:
	door = autofree(HapticsTestKit.manual())
	assert_true(HapticsTestKit.no_ramp(door))
	room = TEST_ROOM.instantiate() as TestRoom
	player = room.get_node(^"Player") as Player
	# The player scene's own probe, pointed at this test's manually stepped door before it
	# enters the tree.
	probe = player.get_node(^"HapticProbe") as HapticProbe
	probe.haptics = door
	var material: HapticMaterial = HapticMaterial.new()
	material.stiffness = K
	material.friction = B
	probe.default_material = material
	add_child_autofree(room)


func _run_frames(count: int) -> void:
	for i: int in count:
		await get_tree().physics_frame
		HapticsTestKit.run(door, TICKS_PER_FRAME)


func _hand(normalized: Vector2) -> void:
	assert_true(HapticsTestKit.set_hand_m(door, normalized * 0.1))


func _part(part: HapticMovementFacts.MovementForce) -> Vector2:
	return HapticsTestKit.movement_part(door, part)


func _add_wall(through: Vector2, normal: Vector2) -> StaticBody2D:
	var wall: StaticBody2D = StaticBody2D.new()
	var shape: CollisionShape2D = CollisionShape2D.new()
	var rect: RectangleShape2D = RectangleShape2D.new()
	rect.size = Vector2(40.0, 600.0)
	shape.shape = rect
	wall.add_child(shape)
	wall.rotation = normal.angle() - PI
	wall.position = through - normal * 20.0
	room.add_child(wall)
	return wall


func _projection(input: Vector2, normal: Vector2) -> Vector2:
	return normal * input.dot(normal)


func _contact_normal() -> Vector2:
	var contacts: Array[HapticContact] = probe.last_frame.contacts
	assert_gt(contacts.size(), 0, "the probe reports a contact")
	if contacts.is_empty():
		return Vector2.ZERO
	return contacts[0].normal


func test_pushing_right_into_the_wall_is_pushed_back_left_with_k_p() -> void:
	_hand(Vector2.RIGHT)
	await _run_frames(200)
	assert_almost_eq(player.position.x, 1240.0 - 18.0, 3.0, "the player is at the wall")
	var i: Vector2 = door.get_input_vector()
	var f_n: Vector2 = _part(NORMAL)
	assert_almost_eq(_contact_normal(), Vector2.LEFT, 0.01)
	assert_lt(f_n.x, -0.1, "pushed back left")
	assert_almost_eq(f_n, -K * _projection(i, Vector2.LEFT), 1e-3)


func test_the_force_scale_reaches_a_wall_without_any_material() -> void:
	# No material on the wall and none on the probe: the servo's default material, and
	# still the servo's force scale (it used to be multiplied into materials only).
	probe.default_material = null
	var default_k: float = HapticsTestKit.movement(door).force_model.default_contact.stiffness_n
	door.force_scale = 0.5
	_hand(Vector2.RIGHT)
	await _run_frames(200)
	var contacts: Array[HapticContact] = probe.last_frame.contacts
	if assert_gt(contacts.size(), 0, "at the wall"):
		assert_null(contacts[0].material, "the frame names no material")
	var i: Vector2 = door.get_input_vector()
	var f_n: Vector2 = _part(NORMAL)
	assert_lt(f_n.x, -0.1, "pushed back left")
	assert_almost_eq(f_n, -0.5 * default_k * _projection(i, Vector2.LEFT), 1e-3)


func test_walls_at_thirty_forty_five_and_one_hundred_thirty_five_degrees() -> void:
	for degrees: float in [30.0, 45.0, 135.0]:
		var normal: Vector2 = Vector2.LEFT.rotated(deg_to_rad(degrees))
		player.position = Vector2(640.0, 360.0)
		player.velocity = Vector2.ZERO
		var wall: StaticBody2D = _add_wall(player.position - normal * 60.0, normal)
		_hand(-normal)
		await _run_frames(60)
		var i: Vector2 = door.get_input_vector()
		var f_n: Vector2 = _part(NORMAL)
		assert_almost_eq(_contact_normal(), normal, 0.02, "contact normal at %d°" % degrees)
		assert_gt(f_n.length(), 0.1, "force at %d°" % degrees)
		assert_almost_eq(f_n.normalized(), normal, 0.02, "along the wall's normal at %d°" % degrees)
		assert_almost_eq(f_n.length(), K * absf(i.dot(normal)), 0.02 * K)
		wall.free()
		_hand(Vector2.ZERO)
		await _run_frames(15)


func test_sliding_along_the_floor_feels_friction_against_the_motion() -> void:
	player.position = Vector2(300.0, 600.0)
	_hand(Vector2(0.7, 0.5))
	await _run_frames(60)
	assert_almost_eq(_contact_normal(), Vector2.UP, 0.01, "on the floor")
	var i: Vector2 = door.get_input_vector()
	var friction: Vector2 = _part(FRICTION)
	var tangential: Vector2 = i - _projection(i, Vector2.UP)
	assert_gt(player.velocity.x, 10.0, "sliding right")
	assert_lt(friction.x, -0.05, "friction points left")
	assert_almost_eq(friction, -B * tangential, 1e-3)


func test_no_contact_means_no_continuous_force() -> void:
	_hand(Vector2(0.3, -0.2))
	await _run_frames(10)
	assert_eq(probe.last_frame.contacts.size(), 0)
	assert_almost_eq(door.get_forces().continuous, Vector2.ZERO, 1e-5)


func _drop_crate(mass: float) -> RigidBody2D:
	var crate: RigidBody2D = RigidBody2D.new()
	crate.mass = mass
	crate.collision_layer = 4  # props
	crate.collision_mask = 1 | 2 | 4  # world, player, props
	var shape: CollisionShape2D = CollisionShape2D.new()
	var rect: RectangleShape2D = RectangleShape2D.new()
	rect.size = Vector2(40.0, 40.0)
	shape.shape = rect
	crate.add_child(shape)
	crate.position = player.position + Vector2(0.0, -200.0)
	room.add_child(crate)
	return crate


func _weight_under_crate(mass: float) -> Dictionary:
	# A solid floor: the room's outline is a thin segment chain, which the player can be
	# pushed through when it recovers from the crate's overlap.
	var floor_body: StaticBody2D = _add_wall(Vector2(400.0, 676.0), Vector2.UP)
	player.position = Vector2(400.0, 676.0 - 18.0)
	_hand(Vector2.ZERO)
	var crate: RigidBody2D = _drop_crate(mass)
	var peak_impact: float = 0.0
	var impact_at_rest: float = 0.0
	for frame: int in 150:
		await get_tree().physics_frame
		for tick: int in TICKS_PER_FRAME:
			door.servo.step(0.001)
			var impact: Vector2 = door.get_forces().impact
			peak_impact = maxf(peak_impact, impact.length())
			if frame >= 140:
				impact_at_rest = maxf(impact_at_rest, impact.length())
	var weight: Vector2 = _part(WEIGHT)
	crate.free()
	floor_body.free()
	await _run_frames(5)
	return {"weight": weight, "peak_impact": peak_impact, "impact_at_rest": impact_at_rest}


func test_a_crate_landing_on_the_player_is_an_impact_then_a_steady_weight() -> void:
	var light: Dictionary = await _weight_under_crate(1.0)
	var heavy: Dictionary = await _weight_under_crate(2.0)
	var light_weight: Vector2 = light["weight"]
	var heavy_weight: Vector2 = heavy["weight"]
	assert_gt(light["peak_impact"], 0.05, "the landing is felt as a transient")
	assert_lt(light["impact_at_rest"], 0.01, "which has died away")
	assert_gt(light_weight.y, 0.5, "the weight pushes down")
	assert_almost_eq(light_weight.x, 0.0, 0.05)
	assert_almost_eq(heavy_weight.y / light_weight.y, 2.0, 0.1, "proportional to mass")


func test_standing_on_a_crate_is_not_felt_as_weight() -> void:
	var crate: RigidBody2D = _drop_crate(2.0)
	crate.position = Vector2(400.0, 680.0 - 4.0 - 20.0)
	player.position = Vector2(400.0, crate.position.y - 20.0 - 18.0 - 1.0)
	_hand(Vector2(0.0, 0.5))
	await _run_frames(40)
	assert_almost_eq(_part(WEIGHT), Vector2.ZERO, 1e-4)


func _add_water(rect: Rect2) -> WaterVolume:
	var water: WaterVolume = WaterVolume.new()
	water.drag_coefficient = 0.6
	water.inertia_force = 0.4
	var shape: CollisionShape2D = CollisionShape2D.new()
	var box: RectangleShape2D = RectangleShape2D.new()
	box.size = rect.size
	shape.shape = box
	water.add_child(shape)
	water.position = rect.get_center()
	room.add_child(water)
	return water


func test_water_drags_against_motion_and_pulls_down_until_left() -> void:
	_add_water(Rect2(500.0, 100.0, 300.0, 500.0))
	player.position = Vector2(420.0, 360.0)
	_hand(Vector2.RIGHT)
	var inside_drag: Vector2 = Vector2.ZERO
	var inside_inertia: Vector2 = Vector2.ZERO
	for frame: int in 150:
		await _run_frames(1)
		var in_water: bool = probe.last_frame.in_water
		if in_water and inside_drag == Vector2.ZERO and player.velocity.x > 50.0:
			inside_drag = _part(DRAG)
			inside_inertia = _part(INERTIA)
			var v: Vector2 = player.velocity / probe.pixels_per_metre
			assert_almost_eq(inside_drag, -0.6 * v, 0.01, "F = -c v")
		if player.position.x > 900.0:
			break
	assert_lt(inside_drag.x, -0.05, "drag opposed the motion")
	assert_almost_eq(inside_inertia, Vector2(0.0, 0.4), 1e-4, "inertia points down")
	assert_gt(player.position.x, 900.0, "the player left the water")
	await _run_frames(2)
	assert_almost_eq(_part(DRAG), Vector2.ZERO, 1e-4)
	assert_almost_eq(_part(INERTIA), Vector2.ZERO, 1e-4)


func test_the_probe_works_on_a_rigid_body_too() -> void:
	var ball: RigidBody2D = RigidBody2D.new()
	var shape: CollisionShape2D = CollisionShape2D.new()
	var circle: CircleShape2D = CircleShape2D.new()
	circle.radius = 16.0
	shape.shape = circle
	ball.add_child(shape)
	ball.position = Vector2(200.0, 600.0)
	var ball_probe: HapticProbe = HapticProbe.new()
	ball_probe.haptics = door
	ball.add_child(ball_probe)
	room.add_child(ball)
	await _run_frames(100)
	var contacts: Array[HapticContact] = ball_probe.last_frame.contacts
	assert_gt(contacts.size(), 0, "resting on the floor")
	if not contacts.is_empty():
		assert_almost_eq(contacts[0].normal, Vector2.UP, 0.05)
