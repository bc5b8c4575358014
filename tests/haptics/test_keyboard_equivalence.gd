extends TestSuite
## Acceleration control is the same whichever way the input vector arrives: the arrow keys
## held right, or the haptic device's stylus pushed to the right edge of its workspace.

const TEST_ROOM := preload("res://game/levels/test_room.tscn")

var _mode_before: StringName = &""


func before_each() -> void:
	_mode_before = Haptics.control_mode


func after_each() -> void:
	Input.action_release(&"move_right")
	Haptics.control_mode = _mode_before


func _velocity_after(frames: int, server: HapticsServer) -> Vector2:
	var room: TestRoom = TEST_ROOM.instantiate() as TestRoom
	var probe: HapticProbe = room.get_node(^"Player/HapticProbe") as HapticProbe
	if server != null:
		probe.server = server
	add_child_autofree(room)
	var player: Player = room.player
	for i: int in frames:
		await get_tree().physics_frame
		if server != null:
			for tick: int in 20:
				server.step(0.001)
	return player.velocity


func test_keys_and_device_give_the_same_acceleration() -> void:
	Haptics.control_mode = Haptics.CONTROL_KEYBOARD
	Input.action_press(&"move_right", 1.0)
	var by_keys: Vector2 = await _velocity_after(5, null)
	Input.action_release(&"move_right")

	Haptics.control_mode = Haptics.CONTROL_DEVICE
	var server: HapticsServer = HapticsServer.new()
	assert_true(server.open_device("simulated"))
	# Beyond the workspace edge: the stylus rests on it, so the input vector is exactly 1.
	assert_true(server.set_hand_target(Vector2(0.3, 0.0)))
	for tick: int in 300:
		server.step(0.001)
	assert_almost_eq(server.get_input_vector(), Vector2.RIGHT, 1e-4)
	var by_device: Vector2 = await _velocity_after(5, server)
	server.close_device()

	assert_gt(by_keys.x, 100.0, "the keys accelerated the player")
	assert_almost_eq(by_device, by_keys, 0.01)
