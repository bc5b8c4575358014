extends TestSuite
## Level 1 steered with the arrow keys through the default door (the simulated hand follows
## the keys, the device's position is the input): a key tapped moves the sub a short way, and
## letting go stops it at once, as a newcomer without a device expects (issue 35 found a
## tap carrying the sub a whole screen and stopping it needing the opposite key).

const SLOW := true
const LEVEL_1 := preload("res://game/levels/level_1.tscn")

## Physics frames a key is held (0.5 s), and the frames after that the sub must stop within.
const HELD_FRAMES: int = 25
const STOP_FRAMES: int = 20
## A tap carries the sub less than a fifth of the screen's height (720 px), and it coasts
## less than two of its own lengths (36 px) after the key comes up.
const TAP_MOST_PX: float = 144.0
const COAST_MOST_PX: float = 72.0

## The arrow keys, pressed and let go as key events: what a keyboard sends (the door reads the
## keys themselves while it feeds the move actions from the device).
const KEYS: Array[Key] = [KEY_RIGHT, KEY_UP, KEY_LEFT, KEY_DOWN]


func after_each() -> void:
	for key: Key in KEYS:
		TestKeyboard.send(key, false)


func test_a_key_let_go_stops_the_sub() -> void:
	var level: Level1 = add_child_autofree(LEVEL_1.instantiate()) as Level1
	var player: Player = level.player
	await _frames(50)  # Settled on the beach.
	for key: Key in KEYS:
		var start: Vector2 = player.global_position
		TestKeyboard.send(key, true)
		await _frames(HELD_FRAMES)
		TestKeyboard.send(key, false)
		var let_go: Vector2 = player.global_position
		var stopped_after: int = -1
		for i: int in STOP_FRAMES:
			await get_tree().physics_frame
			if player.velocity.length() < 10.0:
				stopped_after = i + 1
				break
		var tap: float = let_go.distance_to(start)
		var coast: float = player.global_position.distance_to(let_go)
		var what: String = (
			"%s: held %d frames, %.0f px; coasted %.0f px"
			% [OS.get_keycode_string(key), HELD_FRAMES, tap, coast]
		)
		assert_gt(tap, 20.0, what + ": the key moved the sub")
		assert_lt(tap, TAP_MOST_PX, what)
		assert_lt(coast, COAST_MOST_PX, what)
		assert_gt(stopped_after, 0, what + ": still moving %d frames after" % STOP_FRAMES)
		await _frames(10)


func _frames(count: int) -> void:
	for i: int in count:
		await get_tree().physics_frame
