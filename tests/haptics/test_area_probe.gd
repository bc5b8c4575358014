extends TestSuite
## A player that is an [Area2D] (Godot's "Dodge the Creeps" tutorial player) with a
## [HapticAreaProbe]: a mob that runs into it is a hit felt at the speed they closed in,
## pushing the hand away from the mob, also when the player moves in _process at a frame rate
## other than the tick rate, and when what hits it is an area moved by position; and the one
## line a kill zone calls on either probe.

const PX_PER_M := 100.0
const HARD := preload("res://addons/haptics/materials/hard.tres")

var door: HapticsTestKit.Door = null
var max_fps_before: int = 0
var world: Node2D = null
var player: Area2D = null
var probe: HapticAreaProbe = null


func before_each() -> void:
	max_fps_before = Engine.max_fps
	door = autofree(HapticsTestKit.manual())
	assert_true(HapticsTestKit.no_ramp(door))
	world = Node2D.new()
	player = Area2D.new()
	player.add_child(_circle(16.0))
	player.position = Vector2(400.0, 300.0)
	probe = HapticAreaProbe.new()
	probe.haptics = door
	probe.pixels_per_metre = PX_PER_M
	player.add_child(probe)
	world.add_child(player)
	add_child_autofree(world)


func after_each() -> void:
	Engine.max_fps = max_fps_before


func _circle(radius: float) -> CollisionShape2D:
	var shape: CollisionShape2D = CollisionShape2D.new()
	var circle: CircleShape2D = CircleShape2D.new()
	circle.radius = radius
	shape.shape = circle
	return shape


# A mob as the tutorial's: a rigid body without gravity flying at [param velocity] px/s.
func _mob(at: Vector2, velocity: Vector2) -> RigidBody2D:
	var mob: RigidBody2D = RigidBody2D.new()
	mob.gravity_scale = 0.0
	mob.add_child(_circle(16.0))
	mob.position = at
	mob.linear_velocity = velocity
	mob.set_meta(&"haptic_material", HARD)
	world.add_child(mob)
	return mob


# The largest impact force over [param frames] physics frames, the servo stepped at 1 kHz.
func _peak_impact(frames: int) -> Vector2:
	var peak: Vector2 = Vector2.ZERO
	for frame: int in frames:
		await get_tree().physics_frame
		for tick: int in roundi(1000.0 / Engine.physics_ticks_per_second):
			HapticsTestKit.run(door, 1)
			var impact: Vector2 = door.get_forces().impact
			if impact.length() > peak.length():
				peak = impact
	return peak


func test_a_mob_running_into_an_area_player_is_a_hit_pushing_away_from_it() -> void:
	var hits: Array[float] = []
	probe.impact.connect(func(_c: Object, _d: Vector2, speed: float) -> void: hits.append(speed))
	_mob(player.position + Vector2(-120.0, 0.0), Vector2(235.0, 0.0))
	var peak: Vector2 = await _peak_impact(60)
	assert_eq(hits.size(), 1, "one hit")
	if hits.size() == 1:
		assert_almost_eq(hits[0], 2.35, 0.1, "at the speed the mob came in, m/s")
	assert_gt(peak.length(), 1.0, "felt: over 1 N with hard at 2.35 m/s")
	assert_gt(peak.x, 0.0, "pushed away from the mob (it came from the left)")


func test_a_player_running_into_a_still_mob_is_a_hit_too() -> void:
	_mob(player.position + Vector2(0.0, -100.0), Vector2.ZERO)
	var hits: Array[float] = []
	probe.impact.connect(func(_c: Object, _d: Vector2, speed: float) -> void: hits.append(speed))
	for frame: int in 40:
		player.position += Vector2(0.0, -4.0)  # 240 px/s at 60 ticks a second, by position
		await get_tree().physics_frame
	assert_eq(hits.size(), 1, "one hit")
	if hits.size() == 1:
		assert_almost_eq(hits[0], 4.0 * Engine.physics_ticks_per_second / PX_PER_M, 0.2)


func test_a_kill_zone_is_felt_with_one_line_on_either_probe() -> void:
	probe.hit(Vector2.UP, 3.0, HARD)
	var peak: Vector2 = await _peak_impact(5)
	assert_gt(peak.length(), 1.0, "the area probe's hit")
	assert_lt(peak.y, 0.0, "along the direction given")
	var body: CharacterBody2D = CharacterBody2D.new()
	body.add_child(_circle(10.0))
	var body_probe: HapticProbe = HapticProbe.new()
	body_probe.haptics = door
	body_probe.report_scale = false
	body.add_child(body_probe)
	world.add_child(body)
	await get_tree().physics_frame
	body_probe.hit(Vector2.LEFT, 3.0, HARD)
	peak = await _peak_impact(5)
	assert_gt(peak.length(), 1.0, "the body probe's hit")
	assert_lt(peak.x, 0.0)
	await _peak_impact(60)  # The hit has rung out.
	body_probe.hit(Vector2.ZERO, 3.0)
	body_probe.hit(Vector2(NAN, 0.0), 3.0)
	body_probe.hit(Vector2.UP, NAN)
	var after: Vector2 = await _peak_impact(5)
	assert_lt(after.length(), 1e-3, "nothing from a direction or speed of nothing")


func test_a_player_moved_in_process_is_hit_at_its_speed_whatever_the_frame_rate() -> void:
	# Dodge the Creeps moves its player in _process. At 1.5 frames a tick the player moves one
	# or two frames' way between two ticks: measured per tick that was 2/3 or 4/3 of its speed.
	Engine.max_fps = roundi(Engine.physics_ticks_per_second * 1.5)
	var mover: ProcessMover = ProcessMover.new()
	mover.target = player
	mover.velocity = Vector2(0.0, -400.0)
	world.add_child(mover)
	world.move_child(mover, 0)
	_mob(player.position + Vector2(0.0, -120.0), Vector2.ZERO)
	var hits: Array[float] = []
	probe.impact.connect(func(_c: Object, _d: Vector2, speed: float) -> void: hits.append(speed))
	await wait_until(func() -> bool: return not hits.is_empty(), 3.0)
	mover.velocity = Vector2.ZERO
	await wait_process_frames(2)
	assert_eq(hits.size(), 1, "one hit")
	if hits.size() == 1:
		assert_almost_eq(hits[0], 4.0, 0.2, "at the 400 px/s the player came in, m/s")
	assert_almost_eq(probe.velocity_px().length(), 0.0, 1.0, "still once it stops")


func test_an_area_moved_by_position_into_a_still_player_is_a_hit_at_its_speed() -> void:
	# A bullet that is an Area2D moved by its position, in _process or in _physics_process: its
	# speed is known only from how it moves (it was 0 on entering: no hit).
	Engine.max_fps = roundi(Engine.physics_ticks_per_second * 1.5)
	for in_physics: bool in [false, true]:
		var bullet: Area2D = Area2D.new()
		bullet.add_child(_circle(4.0))
		bullet.position = player.position + Vector2(-100.0, 0.0)
		world.add_child(bullet)
		var mover: ProcessMover = ProcessMover.new()
		mover.target = bullet
		mover.velocity = Vector2(300.0, 0.0)
		mover.in_physics = in_physics
		world.add_child(mover)
		var hits: Array[Vector2] = []
		var record: Callable = func(_c: Object, direction: Vector2, speed: float) -> void:
			hits.append(direction * speed)
		probe.impact.connect(record)
		await wait_until(func() -> bool: return not hits.is_empty(), 3.0)
		probe.impact.disconnect(record)
		var moved: String = "moved in _physics_process" if in_physics else "moved in _process"
		assert_eq(hits.size(), 1, "one hit, %s" % moved)
		if hits.size() == 1:
			assert_almost_eq(hits[0], Vector2(3.0, 0.0), 0.15, "its 3 m/s, pushed away, %s" % moved)
		mover.free()
		bullet.free()
		await wait_physics_frames(2)


## Moves [member target] at [member velocity] px/s by its position, in
## [method Node._process] (as the tutorial's player moves itself) or, with
## [member in_physics], in [method Node._physics_process].
class ProcessMover:
	extends Node
	var target: Node2D = null
	var velocity: Vector2 = Vector2.ZERO
	var in_physics: bool = false

	func _process(delta: float) -> void:
		if not in_physics:
			target.position += velocity * delta

	func _physics_process(delta: float) -> void:
		if in_physics:
			target.position += velocity * delta
