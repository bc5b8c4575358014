extends "res://tests/foundation/room_suite.gd"
## The test room as a real scene: instanced, stepped at 50 Hz, the body steered into walls.

## Runs scenes or processes for seconds: make check (--quick) leaves it out.
const SLOW := true


func test_physics_runs_at_fifty_hertz() -> void:
	assert_eq(Engine.physics_ticks_per_second, 50)
	assert_true(ProjectSettings.get_setting("physics/common/physics_interpolation"))


func test_input_accelerates_the_body_up_to_its_top_speed() -> void:
	_player.input_vector = Vector2.RIGHT
	await wait_physics_frames(2)
	assert_gt(_player.velocity.x, 0.0)
	await wait_physics_frames(10)
	assert_almost_eq(_player.velocity.length(), _player.max_speed, 1.0)


func test_steering_right_stops_at_the_right_wall() -> void:
	var bumps: Array[Vector2] = []
	_room.player_bumped.connect(
		func(_collider: Object, normal: Vector2, _speed: float) -> void: bumps.append(normal)
	)
	_player.input_vector = Vector2.RIGHT
	await wait_physics_frames(250)
	# Outline wall centre line is x = 1240, drawn 8 px wide; the body's radius is 18.
	assert_almost_eq(_player.position.x, 1240.0 - 18.0, 2.0)
	assert_gt(bumps.size(), 0, "a bump was reported")
	assert_almost_eq(bumps[0], Vector2.LEFT, 0.01)


func test_no_input_brakes_to_rest() -> void:
	_player.velocity = Vector2(200.0, 0.0)
	_player.input_vector = Vector2.ZERO
	await wait_physics_frames(15)
	assert_almost_eq(_player.velocity, Vector2.ZERO, 0.01)
