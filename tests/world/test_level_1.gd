extends TestSuite
## Level 1 as a real scene: the Level contract, the autopilot run from start to goal,
## crates (settling, stacking on the player, floating and sinking), pearls and the goal.

## Runs scenes or processes for seconds: make check (--quick) leaves it out.
const SLOW := true

const LEVEL_1 := preload("res://game/levels/level_1.tscn")
const CRATE := preload("res://game/props/crate.tscn")
const HEAVY_CRATE := preload("res://game/props/crate_heavy.tscn")

## Game-time budget of the autopilot run, in physics frames (50 per second).
const AUTOPILOT_FRAME_BUDGET: int = 50 * 60
## Physics runs this many times faster than real time during the long runs (each tick is
## still 1/50 s of game time; see _fast_forward).
const FAST_FORWARD: int = 4

var _level: Level1 = null
var _player: Player = null


func before_each() -> void:
	_level = add_child_autofree(LEVEL_1.instantiate()) as Level1
	_player = _level.player
	_player.use_keyboard = false
	# The test steers the sub itself, not through the haptic device.
	(_player.get_node(^"HapticProbe") as HapticProbe).drive_input = false


func after_each() -> void:
	_fast_forward(1)


func test_level_follows_the_contract() -> void:
	assert_true(_level is Level)
	assert_not_null(_player)
	assert_eq(_player, _level.get_node(^"Player"))
	var start: Vector2 = (_level.get_node(^"Start") as Node2D).global_position
	assert_almost_eq(_level.get_spawn_position(), start, 0.01)
	assert_almost_eq(_player.global_position, start, 0.01, "the player starts at Start")
	var path: PackedVector2Array = _level.get_autopilot_path()
	assert_gt(path.size(), 10)
	assert_almost_eq(path[0], start, 1.0, "the path begins at the start")
	var goal: Goal = _level.get_node(^"Goal") as Goal
	assert_lt(path[path.size() - 1].distance_to(goal.global_position), 80.0, "and ends at the goal")
	assert_eq(_level.total, 12, "pearls")
	var camera: Camera2D = _player.get_node(^"Camera2D") as Camera2D
	assert_true(camera.enabled)
	assert_eq(camera.limit_right, 8960)


func test_world_is_several_screens_wide_with_every_material() -> void:
	assert_gt(_level.world_rect.size.x, 1280.0 * 6.0)
	var names: Array[String] = []
	for body: Node in _level.get_node(^"Terrain").get_children():
		var material: HapticMaterial = HapticMaterial.of(body)
		if assert_not_null(material, "%s has a haptic material" % body.name):
			names.append(material.resource_name)
	for expected: String in ["hard", "soft", "slippery"]:
		assert_has(names, expected)
	for crate: Node in _level.get_node(^"Crates").get_children():
		assert_not_null(HapticMaterial.of(crate), "%s has a haptic material" % crate.name)


func test_autopilot_reaches_the_goal() -> void:
	set_timeout(AUTOPILOT_FRAME_BUDGET / 50.0 / FAST_FORWARD + 20.0)
	var reached: Array[int] = []
	_level.goal_reached.connect(func() -> void: reached.append(1))
	var autopilot: Autopilot = Autopilot.new(_level.get_autopilot_path())
	_fast_forward(FAST_FORWARD)
	var frames: int = 0
	var stuck_frames: int = 0
	var last_index: int = 0
	while reached.is_empty() and frames < AUTOPILOT_FRAME_BUDGET:
		await get_tree().physics_frame
		autopilot.drive(_player, 1.0 / 50.0)
		frames += 1
		stuck_frames = 0 if autopilot.index != last_index else stuck_frames + 1
		last_index = autopilot.index
		if stuck_frames > 50 * 8:
			break
	_fast_forward(1)
	print("    autopilot: %d frames (%.1f s of game time)" % [frames, frames / 50.0])
	assert_eq(
		reached.size(),
		1,
		(
			"goal reached once; waypoint %d of %d, player at %s"
			% [autopilot.index, autopilot.path.size(), _player.global_position]
		)
	)
	assert_true(_level.is_goal_reached)


func test_crates_settle() -> void:
	await wait_physics_frames(150)
	var crates: Array[Node] = _level.get_node(^"Crates").get_children()
	for node: Node in crates:
		var crate: Crate = node as Crate
		if crate.buoyancy > 0.0:
			continue
		assert_lt(crate.linear_velocity.length(), 5.0, "%s at rest" % crate.name)
	# The stack on the tunnel roof is still standing: the top crate is three crates high.
	var top: Crate = _level.get_node(^"Crates/Crate6") as Crate
	assert_almost_eq(top.global_position.y, 520.0 - 24.0 - 2.0 * 48.0, 3.0)


func test_crate_falls_and_rests_on_the_player() -> void:
	# In the crate hall (air, floor at y = 700, ceiling near 400): the sub hovers, a crate
	# falls on it from about two crate heights.
	_player.global_position = Vector2(3100.0, 620.0)
	_player.reset_physics_interpolation()
	var crate: Crate = CRATE.instantiate() as Crate
	crate.position = Vector2(3100.0, 480.0)
	_level.add_child(crate)
	var bumps: Array[Vector2] = []
	_level.player_bumped.connect(
		func(collider: Object, normal: Vector2, _speed: float) -> void:
			if collider == crate:
				bumps.append(normal)
	)
	await wait_physics_frames(100)
	assert_gt(bumps.size(), 0, "the crate hit the player")
	if bumps.size() > 0:
		assert_almost_eq(bumps[0], Vector2.DOWN, 0.05, "normal from crate toward player")
	assert_lt(crate.linear_velocity.length(), 2.0, "the crate is at rest")
	var gap: float = _player.global_position.y - crate.global_position.y
	assert_almost_eq(gap, 24.0 + Player.RADIUS, 1.5, "the crate lies on the hull")
	assert_lt(_player.global_position.y, 640.0, "the sub holds the crate up, sagging little")
	var touching: bool = false
	for i: int in _player.get_slide_collision_count():
		var collision: KinematicCollision2D = _player.get_slide_collision(i)
		if collision.get_collider() == crate:
			touching = true
			assert_gt(collision.get_normal().y, 0.95, "resting contact normal points down")
	assert_true(touching, "the resting crate is a current slide contact")


func test_crates_float_or_sink_by_density() -> void:
	var pool: WaterVolume = _level.get_node(^"Water/Pool") as WaterVolume
	var light: Crate = CRATE.instantiate() as Crate
	light.position = Vector2(5600.0, 950.0)
	var heavy: Crate = HEAVY_CRATE.instantiate() as Crate
	heavy.position = Vector2(5500.0, 700.0)
	_level.add_child(light)
	_level.add_child(heavy)
	assert_lt(light.density, pool.density)
	assert_gt(heavy.density, pool.density)
	await wait_physics_frames(200)
	assert_lt(light.global_position.y, 700.0, "the light crate rose to the surface")
	var expected_draft: float = 48.0 * light.density / pool.density
	var bottom: float = light.global_position.y + 24.0
	assert_almost_eq(bottom - pool.get_surface_y(), expected_draft, 6.0, "floats at its draft")
	assert_gt(heavy.global_position.y, 900.0, "the heavy crate sank")


func test_denser_water_floats_a_heavy_crate() -> void:
	var pool: WaterVolume = _level.get_node(^"Water/Pool") as WaterVolume
	pool.density = 3.0
	var heavy: Crate = HEAVY_CRATE.instantiate() as Crate
	heavy.position = Vector2(5600.0, 950.0)
	_level.add_child(heavy)
	await wait_physics_frames(300)
	assert_lt(heavy.global_position.y, 760.0, "rose to the surface")


func test_pearls_count_up() -> void:
	var counts: Array[Vector2i] = []
	_level.item_collected.connect(
		func(collected: int, total: int) -> void: counts.append(Vector2i(collected, total))
	)
	for pearl: Node in _level.get_node(^"Pearls").get_children():
		_player.global_position = (pearl as Node2D).global_position + Vector2(0.0, -8.0)
		_player.reset_physics_interpolation()
		await wait_physics_frames(3)
	assert_eq(counts.size(), 12)
	for i: int in counts.size():
		assert_eq(counts[i], Vector2i(i + 1, 12))
	# Touching a pearl again does not count it twice.
	_player.global_position = (_level.get_node(^"Pearls/Pearl1") as Node2D).global_position
	await wait_physics_frames(3)
	assert_eq(counts.size(), 12)


func test_goal_is_reported_once() -> void:
	var reached: Array[int] = []
	_level.goal_reached.connect(func() -> void: reached.append(1))
	var goal: Node2D = _level.get_node(^"Goal") as Node2D
	_player.global_position = goal.global_position + Vector2(0.0, -40.0)
	await wait_physics_frames(3)
	_player.global_position = goal.global_position + Vector2(-300.0, -80.0)
	await wait_physics_frames(3)
	_player.global_position = goal.global_position + Vector2(0.0, -40.0)
	await wait_physics_frames(3)
	assert_eq(reached.size(), 1)


func test_player_entering_water_is_slowed_and_splashes() -> void:
	_player.global_position = Vector2(2700.0, 690.0)
	_player.reset_physics_interpolation()
	_player.input_vector = Vector2.DOWN
	await wait_physics_frames(40)
	assert_true(_player.in_water)
	assert_almost_eq(_player.velocity.length(), _player.max_speed * _player.water_speed_factor, 1.0)
	_player.input_vector = Vector2.UP
	await wait_physics_frames(40)
	assert_false(_player.in_water)


## Runs physics [param factor] times faster than real time while keeping each tick 1/50 s of
## game time: the engine steps physics ticks_per_second × time_scale... with the step
## delta = time_scale / ticks_per_second, unchanged when both are scaled by [param factor].
func _fast_forward(factor: int) -> void:
	Engine.physics_ticks_per_second = 50 * factor
	Engine.time_scale = float(factor)
	Engine.max_physics_steps_per_frame = 8 * factor
