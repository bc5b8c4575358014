extends TestSuite
## Acceleration control is the same whichever way the input vector arrives: the arrow keys
## held right, or the haptic device's stylus pushed to the right edge of its workspace.

const TEST_ROOM := preload("res://tests/support/room.tscn")

var _mode_before: StringName = &""


func before_each() -> void:
	_mode_before = Haptics.control_mode


func after_each() -> void:
	Input.action_release(&"move_right")
	Haptics.control_mode = _mode_before


# The player's velocity after [param frames] physics frames, its probe talking to
# [param door] (the Haptics autoload when null) and the door's servo stepped with them.
func _velocity_after(frames: int, door: HapticsTestKit.Door) -> Vector2:
	var room: TestRoom = TEST_ROOM.instantiate() as TestRoom
	var probe: HapticProbe = room.get_node(^"Player/HapticProbe") as HapticProbe
	if door != null:
		probe.haptics = door
	add_child_autofree(room)
	var player: Player = room.player
	for i: int in frames:
		await get_tree().physics_frame
		if door != null:
			HapticsTestKit.run(door, 20)
	return player.velocity


func test_keys_and_device_give_the_same_acceleration() -> void:
	Haptics.control_mode = Haptics.CONTROL_KEYBOARD
	Input.action_press(&"move_right", 1.0)
	var by_keys: Vector2 = await _velocity_after(5, null)
	Input.action_release(&"move_right")

	Haptics.control_mode = Haptics.CONTROL_DEVICE
	var door: HapticsTestKit.Door = autofree(HapticsTestKit.manual())
	assert_eq(door.control_mode, Haptics.CONTROL_DEVICE, "the probe's door drives the player")
	# Beyond the workspace edge (kept on it): the stylus rests there, the input vector is 1.
	assert_true(HapticsTestKit.set_hand_m(door, Vector2(0.3, 0.0)))
	assert_true(HapticsTestKit.run(door, 300))
	assert_almost_eq(door.get_input_vector(), Vector2.RIGHT, 1e-4)
	var by_device: Vector2 = await _velocity_after(5, door)

	assert_gt(by_keys.x, 100.0, "the keys accelerated the player")
	assert_almost_eq(by_device, by_keys, 0.01)
