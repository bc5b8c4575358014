extends "res://tests/world/device_suite.gd"
## A rigid-body player built like Godot's 2d/physics_platformer demo's (its first collision
## shape a downward ray, a custom integrator) with its own HapticProbe, on a stage with the
## demo's traps (rigid_stage.gd): every landing and wall hit above the threshold is one
## impact at the speed before the collision, an enemy on its head is felt as weight, the
## seesaw plank under it is one surface and no load, and riding a lift down is at most one
## impact. Each test drives the player through its own controls and asserts what the device
## received (get_forces, stepped 1 ms at a time in step with the 120 Hz physics).

## Runs scenes or processes for seconds: make check (--quick) leaves it out.
const SLOW := true

const RigidStage := preload("res://tests/world/rigid/rigid_stage.gd")
const RigidPlayer := preload("res://tests/world/rigid/rigid_player.gd")
## The demo's physics rate.
const TICKS_PER_SECOND := 120
## The probe scene's material (materials/hard.tres): impact gain, N·s/m.
const IMPACT_GAIN := 0.8
## Below this, newtons, an impact's ring has died away.
const RING_FLOOR_N := 0.05
## Frames of at least this many without a floor make the next floor contact a landing.
const AIRBORNE_FRAMES := 10

var stage: RigidStage = null
var player: RigidPlayer = null
var probe: HapticProbe = null
var _ticks_per_second: int = 0


func before_each() -> void:
	_ticks_per_second = Engine.physics_ticks_per_second
	Engine.physics_ticks_per_second = TICKS_PER_SECOND
	open_door()
	stage = RigidStage.new()
	player = stage.player
	probe = stage.probe
	watch(probe)
	add_child_autofree(stage)
	await run_frames(30)
	impacts.clear()


func after_each() -> void:
	Engine.physics_ticks_per_second = _ticks_per_second


func _metres(px_per_s: float) -> float:
	return px_per_s / probe.pixels_per_metre


# Frames until the player stands again after at least AIRBORNE_FRAMES in the air; -1 if it
# has not within [param limit].
func _until_landed(limit: int) -> int:
	var airborne: int = 0
	for frame: int in limit:
		await run_frames(1)
		if not player.found_floor:
			airborne += 1
		elif airborne >= AIRBORNE_FRAMES:
			return frame
	return -1


func test_every_landing_is_an_impact_at_the_speed_it_fell_with() -> void:
	var first_sample: int = recorder.samples.size()
	for jump: int in 3:
		player.jump = true
		await run_frames(6)
		player.jump = false
		assert_gt(await _until_landed(240), 0, "landing %d" % jump)
		await run_frames(30)
	assert_eq(player.jumps, 3, "three jumps")
	assert_eq(impacts.size(), 3, "one impact per landing (%s)" % [impacts])
	var fall: float = _metres(RigidPlayer.JUMP_VELOCITY)  # 4.1 m/s at the rule's scale
	for impact: Dictionary in impacts:
		var speed: float = impact["speed"]
		var normal: Vector2 = impact["normal"]
		assert_almost_eq(speed, fall, 0.4, "hit at the speed before the floor stopped it")
		assert_almost_eq(normal, Vector2.UP, 0.05, "from the floor")
	var amplitude: float = IMPACT_GAIN * fall
	assert_gt(recorder.peak("total", Vector2.UP, first_sample), 0.6 * amplitude, "felt, N")
	assert_gt(recorder.peak("impact", Vector2.UP, first_sample), 0.6 * amplitude)
	assert_lt(recorder.peak_across("impact", Vector2.UP, first_sample), 0.01, "straight up")
	# Three rings of about 80 ms (hard: 20 ms decay) over about 3 s.
	var ringing: float = recorder.duration("impact", RING_FLOOR_N, first_sample)
	assert_gt(ringing, 1.5, "from the first landing to the last")


func test_a_wall_hit_at_full_run_is_one_impact() -> void:
	var first_sample: int = recorder.samples.size()
	player.move = 1.0
	var hit: bool = false
	for frame: int in 360:
		await run_frames(1)
		if player.position.x > RigidStage.WALL_X - 20.0:
			hit = true
			break
	assert_true(hit, "the player reached the wall")
	await run_frames(60)  # still pushing
	assert_eq(impacts.size(), 1, "one impact (%s)" % [impacts])
	if impacts.is_empty():
		return
	var speed: float = impacts[0]["speed"]
	var normal: Vector2 = impacts[0]["normal"]
	assert_almost_eq(speed, _metres(RigidPlayer.WALK_MAX_VELOCITY), 0.3, "at the run's speed")
	assert_almost_eq(normal, Vector2.LEFT, 0.05, "from the wall")
	var amplitude: float = IMPACT_GAIN * speed
	assert_gt(recorder.peak("impact", Vector2.LEFT, first_sample), 0.6 * amplitude, "felt, N")
	assert_lt(recorder.peak_across("impact", Vector2.LEFT, first_sample), 0.01, "straight back")
	var ringing: float = recorder.duration("impact", RING_FLOOR_N, first_sample)
	assert_gt(ringing, 0.03, "one ring, s")
	assert_lt(ringing, 0.2, "one ring, s")


func test_an_enemy_standing_on_the_head_is_felt_as_weight() -> void:
	var warning: String = probe.shape_warning
	assert_true(warning.contains("Feet (SeparationRayShape2D)"), "warned: %s" % warning)
	assert_true(warning.contains("found above Body"), "warned: %s" % warning)
	var enemy: RigidBody2D = stage.spawn_enemy_above()
	await run_frames(120)
	assert_lt(enemy.position.y, player.position.y, "it stands on the player")
	var resting: Array[HapticLoad] = probe.last_frame.resting
	assert_eq(resting.size(), 1, "one load")
	if resting.size() == 1:
		assert_almost_eq(resting[0].mass_kg, RigidStage.ENEMY_MASS, 1e-4)
		assert_almost_eq(resting[0].normal, Vector2.DOWN, 0.05)
	var per_kg: float = HapticsTestKit.movement(door).force_model.gravity_n_per_kg
	var expected: Vector2 = Vector2.DOWN * RigidStage.ENEMY_MASS * per_kg
	assert_almost_eq(recorder.last("weight"), expected, 0.05 * per_kg, "weight, N")
	assert_gt(recorder.last("total").y, 0.5 * expected.y, "the hand is pressed down")
	var from_above: int = 0
	for impact: Dictionary in impacts:
		var normal: Vector2 = impact["normal"]
		from_above += 1 if normal.dot(Vector2.DOWN) > 0.9 else 0
	assert_eq(from_above, 1, "its landing on the head is one impact (%s)" % [impacts])


func test_the_seesaw_plank_is_one_surface_and_no_load() -> void:
	stage.place_player(RigidStage.SEESAW + Vector2(6.0, -RigidStage.PLANK_SIZE.y * 0.5 - 40.0))
	var on_plank: int = 0
	var doubled: int = 0
	var loaded: int = 0
	for frame: int in 280:
		await run_frames(1)
		var contacts: Array[HapticContact] = probe.last_frame.contacts
		loaded += 1 if not probe.last_frame.resting.is_empty() else 0
		on_plank += 1 if not contacts.is_empty() else 0
		for i: int in contacts.size():
			for j: int in range(i + 1, contacts.size()):
				doubled += 1 if contacts[i].normal.dot(contacts[j].normal) > 0.999 else 0
	assert_gt(on_plank, 200, "it stood on the plank")
	assert_eq(doubled, 0, "no surface counted twice")
	assert_eq(loaded, 0, "the plank under the feet is no load on top")
	assert_lt(impacts.size(), 3, "its landing, at most a second touch as it tips (%s)" % [impacts])


func test_riding_a_lift_down_is_at_most_one_impact() -> void:
	stage.place_player(stage.lift_top_feet())
	await run_frames(30)
	impacts.clear()
	var first_sample: int = recorder.samples.size()
	stage.start_lift()
	var lost: int = 0
	var was_on: bool = true
	for frame: int in int(RigidStage.LIFT_RIDE_S * TICKS_PER_SECOND):
		await run_frames(1)
		stage.advance_lift(1.0 / TICKS_PER_SECOND)
		if was_on and not player.found_floor:
			lost += 1
		was_on = player.found_floor
	assert_gt(stage.lift.position.y, RigidStage.LIFT_BOTTOM.y - 2.0, "the lift came down")
	assert_almost_eq(player.position.x, RigidStage.LIFT_TOP.x, 30.0, "with the player on it")
	print("    lift ride: floor lost %d times" % lost)
	assert_lt(impacts.size(), 2, "lost the lift %d times: %s" % [lost, impacts])
	assert_lt(recorder.duration("impact", RING_FLOOR_N, first_sample), 0.2, "at most one ring, s")


func test_the_scale_check_gives_the_players_height() -> void:
	# The ray reaches from 6 px above the origin to 14 below; the body's top is 12 above.
	var height_px: float = RigidStage.HEAD_ABOVE + RigidStage.FEET_BELOW
	var rule: float = RigidPlayer.GRAVITY / HapticProbe.EARTH_GRAVITY
	assert_almost_eq(probe.pixels_per_metre, rule, 1e-3, "the rule")
	assert_almost_eq(probe.body_height_m(), height_px / probe.pixels_per_metre, 0.005)
	var report: String = probe.scale_report()
	var height: String = "%.2f m tall" % (height_px / probe.pixels_per_metre)
	assert_true(report.contains(height), "%s in: %s" % [height, report])
	assert_true(report.contains("%.1f px/m" % probe.pixels_per_metre), report)
