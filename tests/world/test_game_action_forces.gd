extends "res://tests/world/device_suite.gd"
## The side-scroller's own actions, each from where the player starts it: the hand moves the
## simulated device, the game's avatar (game/player/player.tscn, its own HapticProbe)
## drives into the floor or a wall of the game's room, a game crate lands on it, it dives
## into the game's water. Each test asserts the force the device received on its 1 ms ticks
## (get_forces: total and its parts, newtons, direction, how long), so it fails when the
## force never arrives. (Riding a platform: the side-scroller has none; the rigid-body
## player's lift ride is in test_rigid_player.gd.)

## Runs scenes or processes for seconds: make check (--quick) leaves it out.
const SLOW := true

const TEST_ROOM := preload("res://tests/support/room.tscn")
const CRATE := preload("res://game/props/crate.tscn")
const WATER := preload("res://game/props/water.tscn")
## The probe scene's material (materials/hard.tres) for the room's walls.
const WALL_STIFFNESS := 3.0
const WALL_IMPACT_GAIN := 0.8
## The room's floor and right wall (tests/support/room.tscn's outline), px.
const FLOOR_Y := 680.0
const WALL_X := 1240.0
## Below this, newtons, an impact's ring has died away.
const RING_FLOOR_N := 0.05

var room: TestRoom = null
var player: Player = null
var probe: HapticProbe = null


func before_each() -> void:
	open_door()
	room = TEST_ROOM.instantiate() as TestRoom
	player = room.get_node(^"Player") as Player
	probe = player.get_node(^"HapticProbe") as HapticProbe
	watch(probe)
	add_child_autofree(room)


# The hand drives the avatar at full speed along [param direction] into the room's outline:
# one impact from the surface, felt along [param normal], then the surface's steady push.
func _drive_into(direction: Vector2, normal: Vector2) -> void:
	var first: int = recorder.samples.size()
	hand(direction)
	await run_frames(200)
	assert_eq(impacts.size(), 1, "one impact (%s)" % [impacts])
	if impacts.is_empty():
		return
	var speed: float = impacts[0]["speed"]
	var felt_normal: Vector2 = impacts[0]["normal"]
	assert_almost_eq(felt_normal, normal, 0.05, "from the surface")
	assert_almost_eq(speed, player.max_speed / probe.pixels_per_metre, 0.4, "at full speed, m/s")
	var amplitude: float = minf(WALL_IMPACT_GAIN * speed, 3.0)
	assert_gt(recorder.peak("impact", normal, first), 0.6 * amplitude, "the knock, N")
	assert_gt(recorder.peak("total", normal, first), 0.6 * amplitude, "in the total, N")
	assert_lt(recorder.peak_across("impact", normal, first), 0.01, "along the normal")
	var ringing: float = recorder.duration("impact", RING_FLOOR_N, first)
	assert_gt(ringing, 0.03, "rings, s")
	assert_lt(ringing, 0.2, "and dies away, s")
	# Held against it, the hand is pushed back out of the surface.
	var push: float = recorder.last("total").dot(normal)
	var into: float = -door.get_input_vector().dot(normal)
	assert_gt(into, 0.5, "the hand still pushes in")
	assert_almost_eq(push, WALL_STIFFNESS * into, 0.1 * WALL_STIFFNESS, "steady push, N")


func test_landing_on_the_floor_knocks_then_holds_the_hand_up() -> void:
	await _drive_into(Vector2.DOWN, Vector2.UP)
	assert_almost_eq(player.position.y, FLOOR_Y - Player.RADIUS, 3.0, "on the floor")


func test_hitting_a_wall_knocks_then_holds_the_hand_back() -> void:
	await _drive_into(Vector2.RIGHT, Vector2.LEFT)
	assert_almost_eq(player.position.x, WALL_X - Player.RADIUS, 3.0, "at the wall")


func test_a_crate_landing_on_the_avatar_knocks_down_then_weighs() -> void:
	hand(Vector2.ZERO)
	await run_frames(5)
	var first: int = recorder.samples.size()
	var crate: Crate = CRATE.instantiate() as Crate
	crate.position = player.position + Vector2(0.0, -200.0)
	room.add_child(crate)
	await run_frames(150)
	assert_eq(impacts.size(), 1, "the crate's landing (%s)" % [impacts])
	if not impacts.is_empty():
		var normal: Vector2 = impacts[0]["normal"]
		assert_almost_eq(normal, Vector2.DOWN, 0.1, "from above")
	assert_gt(recorder.peak("impact", Vector2.DOWN, first), 0.5, "the knock, N")
	assert_gt(recorder.peak("total", Vector2.DOWN, first), 0.5, "in the total, N")
	var per_kg: float = HapticsTestKit.movement(door).force_model.gravity_n_per_kg
	var weight: Vector2 = recorder.last("weight")
	assert_almost_eq(weight, Vector2.DOWN * crate.mass * per_kg, 0.1 * crate.mass * per_kg, "N")
	assert_almost_eq(recorder.last("total"), weight, 0.05, "all that is felt, N")


func test_diving_into_water_drags_and_pulls_down_while_inside() -> void:
	var water: WaterVolume = WATER.instantiate() as WaterVolume
	water.position = Vector2(500.0, 200.0)  # 512 × 256 from here
	room.add_child(water)
	player.position = Vector2(400.0, 330.0)
	hand(Vector2.RIGHT)
	var first: int = -1
	var inside_frames: int = 0
	for frame: int in 300:
		await run_frames(1)
		if player.in_water:
			inside_frames += 1
			first = recorder.samples.size() if first < 0 else first
		elif first >= 0:
			break
	assert_gt(inside_frames, 20, "the avatar crossed the water")
	assert_gt(first, -1, "it entered the water")
	if first < 0:
		return
	var drag: float = recorder.peak("drag", Vector2.LEFT, first)
	var speed: float = player.max_speed * player.water_speed_factor / probe.pixels_per_metre
	assert_almost_eq(drag, water.drag_coefficient * speed, 0.15, "drag against the motion, N")
	assert_almost_eq(recorder.peak("inertia", Vector2.DOWN, first), water.inertia_force, 0.01)
	assert_gt(recorder.peak("total", Vector2.LEFT, first), 0.5 * drag, "in the total, N")
	var inside_s: float = float(inside_frames) / Engine.physics_ticks_per_second
	assert_gt(recorder.duration("drag", 0.05, first), 0.5 * inside_s, "felt while inside, s")
	await run_frames(5)
	assert_almost_eq(recorder.last("drag"), Vector2.ZERO, 1e-4, "none once out")
