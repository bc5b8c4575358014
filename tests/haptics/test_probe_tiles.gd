extends TestSuite
## The probe on a gravity platformer's body standing on a [TileMapLayer] floor and running
## into a wall of the same layer: one collider, many tiles. Every tile touched is a contact
## of its own (the floor and the wall are both felt on every physics frame), a new tile is a
## new impact, and tiles take their material from the TileSet's custom data or physics
## material. A wall or ceiling stays a contact on the frames move_and_slide does not report it
## while the body still touches it, and stops being one as soon as the body has left it.

## Runs scenes or processes for seconds: make check (--quick) leaves it out.
const SLOW := true

const K := 2.0
const B := 1.0
const TILE := 32
const FLOOR_ROW := 10
const WALL_COLUMN := 12
const HALF_WIDTH := 10.0
const HALF_HEIGHT := 18.0
## Frames for the smoothed force to settle after the first touch.
const SETTLE_FRAMES := 6
## Farther than this from a surface, in pixels, it must no longer be a contact.
const LEFT_PX := 0.5


## A platformer body as games write them: gravity, run speed from an input vector, reached
## at once or, like Godot's platformer demo, with move_toward at [member acceleration].
class Runner:
	extends CharacterBody2D

	var input_vector: Vector2 = Vector2.ZERO
	var acceleration: float = INF
	var gravity: float = 980.0

	func _physics_process(delta: float) -> void:
		velocity.x = move_toward(velocity.x, input_vector.x * 200.0, acceleration * delta)
		velocity.y += gravity * delta
		move_and_slide()


var door: HapticsTestKit.Door = null
var world: Node2D = null
var layer: TileMapLayer = null
var body: Runner = null
var probe: HapticProbe = null
var ticks_per_second: int = 0


func before_each() -> void:
	ticks_per_second = Engine.physics_ticks_per_second
	door = autofree(HapticsTestKit.manual())
	assert_true(HapticsTestKit.no_ramp(door))
	world = Node2D.new()
	layer = _tile_layer()
	world.add_child(layer)
	for column: int in range(0, WALL_COLUMN + 1):
		layer.set_cell(Vector2i(column, FLOOR_ROW), 0, Vector2i(0, 0))
	for row: int in range(FLOOR_ROW - 4, FLOOR_ROW):
		layer.set_cell(Vector2i(WALL_COLUMN, row), 0, Vector2i(1, 0))
	body = Runner.new()
	var shape: CollisionShape2D = CollisionShape2D.new()
	var rect: RectangleShape2D = RectangleShape2D.new()
	rect.size = Vector2(HALF_WIDTH, HALF_HEIGHT) * 2.0
	shape.shape = rect
	body.add_child(shape)
	body.position = Vector2(4.5 * TILE, FLOOR_ROW * TILE - HALF_HEIGHT)
	probe = HapticProbe.new()
	probe.haptics = door
	var material: HapticMaterial = HapticMaterial.new()
	material.stiffness = K
	material.friction = B
	probe.default_material = material
	body.add_child(probe)
	world.add_child(body)
	add_child_autofree(world)


func after_each() -> void:
	Engine.physics_ticks_per_second = ticks_per_second


# Two tiles: (0, 0) plain, (1, 0) with a haptic material in the custom data layer.
func _tile_layer() -> TileMapLayer:
	var tiles: TileMapLayer = TileMapLayer.new()
	tiles.tile_set = SquareTileSet.make(TILE, 2)
	return tiles


func _wall_material() -> HapticMaterial:
	var source: TileSetAtlasSource = layer.tile_set.get_source(0)
	var material: HapticMaterial = HapticMaterial.new()
	material.stiffness = 3.0
	material.friction = 0.5
	material.impact_gain = 0.8
	source.get_tile_data(Vector2i(1, 0), 0).set_custom_data(HapticMaterial.TILE_LAYER, material)
	return material


# One physics frame, the servo stepped at 1 kHz for as long.
func _frame() -> void:
	await get_tree().physics_frame
	HapticsTestKit.run(door, roundi(1000.0 / Engine.physics_ticks_per_second))


# Godot's platformer demo: 120 ticks per second, strong gravity, and here a slow run-up
# (move_toward by 450 px/s²). Pushed into a wall, the body's speed alternates between 0 and
# one step so small that move_and_slide does not report the wall on many frames.
func _run_up_slowly() -> void:
	Engine.physics_ticks_per_second = 120
	body.acceleration = 450.0
	body.gravity = 2100.0


# Runs right until the wall is a contact (at most [param frames] frames); the frame it was
# first one, or -1.
func _run_to_wall(frames: int) -> int:
	_hand(Vector2.RIGHT)
	for frame: int in frames:
		await _frame()
		if _has_normal(Vector2.LEFT):
			return frame
	return -1


func _hand(normalized: Vector2) -> void:
	assert_true(HapticsTestKit.set_hand_m(door, normalized * 0.1))


func _normal_force() -> Vector2:
	return HapticsTestKit.movement_part(door, HapticMovementFacts.MovementForce.NORMAL)


func _weight() -> Vector2:
	return HapticsTestKit.movement_part(door, HapticMovementFacts.MovementForce.WEIGHT)


func _has_normal(normal: Vector2) -> bool:
	for contact: HapticContact in probe.last_frame.contacts:
		if contact.normal.distance_to(normal) < 0.01:
			return true
	return false


# The material [param contact] names, or one whose gains are -1 when there is no contact or
# it names none.
func _material_of(contact: HapticContact) -> HapticContactMaterial:
	if contact != null and contact.material != null:
		return contact.material
	var none: HapticContactMaterial = HapticContactMaterial.new()
	none.stiffness_n = -1.0
	none.friction_n = -1.0
	return none


func test_a_tile_wall_is_pushed_back_on_every_frame_while_standing_on_the_same_layer() -> void:
	_hand(Vector2.RIGHT)
	var wall_x: float = WALL_COLUMN * TILE - HALF_WIDTH
	var frames_at_wall: int = 0
	var impacts: Array[Vector2] = []
	probe.impact.connect(func(_c: Object, n: Vector2, _s: float) -> void: impacts.append(n))
	for frame: int in 150:
		await _frame()
		if absf(body.position.x - wall_x) > 0.5 or not body.is_on_floor():
			continue
		frames_at_wall += 1
		if frames_at_wall < 3:
			continue  # the smoothed force settles after the first touch
		var i: Vector2 = door.get_input_vector()
		var f_n: Vector2 = _normal_force()
		assert_true(_has_normal(Vector2.UP), "frame %d: the floor is a contact" % frame)
		assert_true(_has_normal(Vector2.LEFT), "frame %d: the wall is a contact" % frame)
		assert_almost_eq(f_n.x, -K * i.x, 0.02 * K, "frame %d: wall push-back k·i" % frame)
		assert_lt(f_n.x, -0.5, "frame %d: pushed away from the wall" % frame)
	assert_gt(frames_at_wall, 60, "the runner reached the wall and stayed there")
	assert_has(impacts, Vector2.LEFT, "running into the wall is an impact")


func test_a_wall_pushed_after_a_slow_run_up_is_felt_on_every_frame() -> void:
	_run_up_slowly()
	assert_gt(await _run_to_wall(300), -1, "the runner reached the wall")
	var lost: PackedInt32Array = []
	var off: PackedStringArray = []
	for frame: int in 240:
		await _frame()
		if frame < SETTLE_FRAMES:
			continue
		var i: Vector2 = door.get_input_vector()
		var f_n: Vector2 = _normal_force()
		if not _has_normal(Vector2.LEFT):
			lost.append(frame)
		if absf(f_n.x + K * i.x) > 0.02 * K or f_n.x > -0.5:
			off.append("%d: %.3f N" % [frame, f_n.x])
	assert_eq(lost, PackedInt32Array(), "frames the wall was not a contact")
	assert_eq(off, PackedStringArray(), "frames the push-back was not k·i")


func test_walking_away_from_a_wall_leaves_it_at_once() -> void:
	_run_up_slowly()
	assert_gt(await _run_to_wall(300), -1, "the runner reached the wall")
	for frame: int in 60:
		await _frame()
	_hand(Vector2.LEFT)
	var stuck: PackedStringArray = []
	var away: int = 0
	for frame: int in 60:
		await _frame()
		var gap: float = WALL_COLUMN * TILE - (body.position.x + HALF_WIDTH)
		if gap > LEFT_PX:
			away += 1
			if _has_normal(Vector2.LEFT):
				stuck.append("%.2f px" % gap)
	assert_gt(away, 30, "the runner walked away")
	assert_eq(stuck, PackedStringArray(), "gaps at which the wall was still a contact")
	assert_almost_eq(_normal_force(), Vector2.ZERO, 1e-6, "no push-back")


func test_a_ceiling_hit_is_a_contact_until_the_body_falls_away() -> void:
	var ceiling_row: int = FLOOR_ROW - 3
	for column: int in range(0, WALL_COLUMN):
		layer.set_cell(Vector2i(column, ceiling_row), 0, Vector2i(0, 0))
	for frame: int in 10:
		await _frame()  # landing from the spawn height
	body.velocity.y = -500.0
	var hit: bool = false
	var stuck: PackedStringArray = []
	for frame: int in 40:
		await _frame()
		var gap: float = (body.position.y - HALF_HEIGHT) - (ceiling_row + 1) * TILE
		hit = hit or _has_normal(Vector2.DOWN)
		if gap > LEFT_PX and _has_normal(Vector2.DOWN):
			stuck.append("%.2f px" % gap)
	assert_true(hit, "the ceiling was hit")
	assert_eq(stuck, PackedStringArray(), "gaps at which the ceiling was still a contact")
	assert_true(body.is_on_floor(), "landed again")


func test_every_new_floor_tile_is_not_an_impact_but_a_new_wall_tile_is() -> void:
	# Walking along the floor crosses tile borders: contacts of the same floor normal
	# continue (no impact per tile), only the wall is hit.
	_hand(Vector2.RIGHT)
	var impacts: Array[Vector2] = []
	probe.impact.connect(func(_c: Object, n: Vector2, _s: float) -> void: impacts.append(n))
	for frame: int in 20:
		await _frame()  # landing from the spawn height
	impacts.clear()
	for frame: int in 120:
		await _frame()
	assert_eq(impacts, [Vector2.LEFT], "one impact: the wall")


func test_a_tile_takes_its_material_from_the_tile_set_custom_data() -> void:
	var material: HapticMaterial = _wall_material()
	_hand(Vector2.RIGHT)
	var found: Dictionary[Vector2, HapticContact] = {}
	for frame: int in 150:
		await _frame()
		for contact: HapticContact in probe.last_frame.contacts:
			found[contact.normal] = contact
	var wall: HapticContactMaterial = _material_of(
		found[Vector2.LEFT] if found.has(Vector2.LEFT) else null
	)
	var ground: HapticContactMaterial = _material_of(
		found[Vector2.UP] if found.has(Vector2.UP) else null
	)
	assert_almost_eq(wall.stiffness_n, material.stiffness, 1e-6, "the wall tile's")
	assert_almost_eq(ground.stiffness_n, K, 1e-6, "the floor: the default")


func test_a_flipped_alternative_tile_feels_like_its_base_tile_unless_given_its_own() -> void:
	var material: HapticMaterial = _wall_material()
	var source: TileSetAtlasSource = layer.tile_set.get_source(0)
	var base: TileData = source.get_tile_data(Vector2i(1, 0), 0)
	var alternative: int = source.create_alternative_tile(Vector2i(1, 0))
	var flipped: TileData = source.get_tile_data(Vector2i(1, 0), alternative)
	flipped.flip_h = true
	flipped.add_collision_polygon(0)
	flipped.set_collision_polygon_points(0, 0, base.get_collision_polygon_points(0, 0))
	for row: int in range(FLOOR_ROW - 4, FLOOR_ROW):
		layer.set_cell(Vector2i(WALL_COLUMN, row), 0, Vector2i(1, 0), alternative)
	assert_gt(await _run_to_wall(150), -1, "the runner reached the flipped wall")
	var wall: HapticContact = null
	for contact: HapticContact in probe.last_frame.contacts:
		if contact.normal == Vector2.LEFT:
			wall = contact
	assert_almost_eq(_material_of(wall).stiffness_n, material.stiffness, 1e-6, "the base tile's")
	assert_almost_eq(_material_of(wall).friction_n, material.friction, 1e-6, "the base tile's")
	var own: HapticMaterial = HapticMaterial.new()
	own.stiffness = 7.0
	flipped.set_custom_data(HapticMaterial.TILE_LAYER, own)
	var cell: Vector2i = Vector2i(WALL_COLUMN, FLOOR_ROW - 1)
	assert_eq(HapticMaterial.of_tile(layer, cell), own, "the alternative's own material wins")
	base.set_custom_data(HapticMaterial.TILE_LAYER, null)
	flipped.set_custom_data(HapticMaterial.TILE_LAYER, null)
	assert_null(HapticMaterial.of_tile(layer, cell), "neither has one: none")


func test_a_physics_material_stands_in_when_no_haptic_material_is_given() -> void:
	var physics: PhysicsMaterial = PhysicsMaterial.new()
	physics.friction = 0.4
	physics.bounce = 0.5
	layer.tile_set.set_physics_layer_physics_material(0, physics)
	var expected: HapticMaterial = HapticMaterial.from_physics_material(physics)
	probe.default_material = null
	await _frame()
	await _frame()
	var contacts: Array[HapticContact] = probe.last_frame.contacts
	assert_eq(contacts.size(), 1, "standing on the floor")
	if contacts.size() == 1:
		var material: HapticContactMaterial = _material_of(contacts[0])
		assert_almost_eq(material.friction_n, expected.friction, 1e-6)
		assert_almost_eq(material.stiffness_n, expected.stiffness, 1e-6)


func test_the_physics_material_mapping() -> void:
	var physics: PhysicsMaterial = PhysicsMaterial.new()
	var reference: HapticMaterial = HapticMaterial.new()
	physics.friction = 1.0
	physics.bounce = 0.0
	var plain: HapticMaterial = HapticMaterial.from_physics_material(physics)
	assert_almost_eq(plain.friction, reference.friction, 1e-6, "friction 1 is the default")
	assert_almost_eq(plain.impact_gain, reference.impact_gain, 1e-6, "no bounce: default")
	physics.friction = 0.0
	physics.bounce = 1.0
	var ice: HapticMaterial = HapticMaterial.from_physics_material(physics)
	assert_almost_eq(ice.friction, 0.0, 1e-6, "frictionless")
	assert_almost_eq(ice.impact_gain, 2.0 * reference.impact_gain, 1e-6, "bouncy: twice")
	physics.friction = 1000.0
	var extreme: HapticMaterial = HapticMaterial.from_physics_material(physics)
	assert_almost_eq(extreme.friction, 100.0, 1e-6, "clamped to the material's range")


func test_own_weight_presses_the_hand_down_only_while_standing_and_only_when_asked() -> void:
	var g: float = HapticsTestKit.movement(door).force_model.gravity_n_per_kg
	for frame: int in 20:
		await _frame()
	assert_true(body.is_on_floor())
	assert_almost_eq(_weight(), Vector2.ZERO, 1e-6, "off by default")
	probe.own_weight_kg = 0.5
	for frame: int in 5:
		await _frame()
	assert_almost_eq(_weight(), Vector2(0.0, 0.5 * g), 1e-3, "m g, down")
	body.position.y -= 200.0  # in the air
	for frame: int in 3:
		await _frame()
	assert_false(body.is_on_floor())
	assert_almost_eq(_weight(), Vector2.ZERO, 1e-3, "not while falling")
