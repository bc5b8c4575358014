extends "res://tests/foundation/room_suite.gd"
## The sub against walls (acceleration control, a floating body): blocked by a wall it keeps
## no velocity into it, so input turned away leaves the wall within two physics ticks (it
## used to keep its full speed into the wall and take about seven ticks to come off); along
## a floor it slides at the top speed; a crate it drives into is still shoved.

## Runs scenes or processes for seconds: make check (--quick) leaves it out.
const SLOW := true

const CRATE := preload("res://game/props/crate.tscn")
## The test room's right wall (its outline's centre line), and its floor.
const WALL_X: float = 1240.0
const FLOOR_Y: float = 680.0


func test_pressed_into_a_wall_the_sub_keeps_no_velocity_into_it() -> void:
	_player.input_vector = Vector2.RIGHT
	await wait_physics_frames(150)
	assert_almost_eq(_player.position.x, WALL_X - Player.RADIUS, 2.0, "at the right wall")
	assert_gt(_player.get_slide_collision_count(), 0, "touching it")
	# At most what one tick of input adds before the wall takes it away again (it used to
	# be the full top speed).
	assert_lt(_player.velocity.x, _player.acceleration / 50.0 + 0.5, "no speed into the wall")


func test_turning_away_leaves_the_wall_within_two_ticks() -> void:
	_player.input_vector = Vector2.RIGHT
	await wait_physics_frames(150)
	var at_wall: float = _player.position.x
	_player.input_vector = Vector2.LEFT
	await wait_physics_frames(1)
	# The first tick moves it away; the physics may still report the wall it starts from
	# within its safe margin on that tick, never on the next.
	assert_lt(_player.position.x, at_wall - 0.5, "moving away at the first tick")
	assert_lt(_player.velocity.x, 0.0)
	var first: int = _player.get_slide_collision_count()
	await wait_physics_frames(1)
	print(
		(
			"    contacts after the first tick: %d, after the second: %d"
			% [first, _player.get_slide_collision_count()]
		)
	)
	assert_eq(_player.get_slide_collision_count(), 0, "off the wall after two ticks")


func test_sliding_along_the_floor_reaches_the_top_speed() -> void:
	# Pressed diagonally into the floor the sub used to share its top speed with the blocked
	# downward part (0.6 of it along the floor); now the floor takes that part away.
	_player.position = Vector2(100.0, FLOOR_Y - Player.RADIUS - 20.0)
	_player.reset_physics_interpolation()
	_player.input_vector = Vector2(0.6, 0.8)
	await wait_physics_frames(40)
	assert_gt(_player.get_slide_collision_count(), 0, "on the floor")
	assert_gt(_player.velocity.x, 0.95 * _player.max_speed, "along it at the top speed")
	assert_lt(_player.velocity.y, _player.acceleration / 50.0 + 0.5, "not into it")


func test_a_crate_the_sub_drives_into_is_still_shoved() -> void:
	var crate: RigidBody2D = CRATE.instantiate() as RigidBody2D
	crate.position = Vector2(260.0, FLOOR_Y - 24.0)
	_room.add_child(crate)
	_player.position = Vector2(180.0, FLOOR_Y - 24.0)
	_player.reset_physics_interpolation()
	await wait_physics_frames(20)
	var before: float = crate.position.x
	_player.input_vector = Vector2.RIGHT
	await wait_physics_frames(60)
	assert_gt(crate.position.x - before, 60.0, "the crate moved right")
	assert_gt(_player.position.x, 200.0, "the sub followed it")
