extends TestSuite
## The mouse steers the simulated hand only while the player holds its left button down in
## the game, as a stick gripped where the press began: a pointer left anywhere steers
## nothing, a click on a control grips nothing, letting go centres the hand, and the keys
## win over it.

var _follows: bool = true
var _control_mode: StringName = &""


func before_each() -> void:
	_follows = Haptics.hand_follows_input
	_control_mode = Haptics.control_mode
	Haptics.hand_follows_input = true
	Haptics.control_mode = Haptics.CONTROL_DEVICE
	_button(Vector2(50.0, 50.0), false)


func after_each() -> void:
	_button(Vector2(50.0, 50.0), false)
	Haptics.hand_follows_input = _follows
	Haptics.control_mode = _control_mode
	Haptics.device.set_hand_target(Vector2.ZERO)


# Events arrive in window pixels; the test speaks in the viewport's (the window may be
# stretched).
func _window(at: Vector2) -> Vector2:
	return get_viewport().get_screen_transform() * at


func _motion(to: Vector2) -> void:
	var motion: InputEventMouseMotion = InputEventMouseMotion.new()
	motion.position = _window(to)
	motion.global_position = _window(to)
	Input.parse_input_event(motion)
	Input.flush_buffered_events()


func _button(at: Vector2, pressed: bool) -> void:
	var button: InputEventMouseButton = InputEventMouseButton.new()
	button.button_index = MOUSE_BUTTON_LEFT
	button.position = _window(at)
	button.global_position = _window(at)
	button.pressed = pressed
	Input.parse_input_event(button)
	Input.flush_buffered_events()


func _hand_after_frames(frames: int = 5) -> Vector2:
	for i: int in frames:
		await get_tree().physics_frame
	return Haptics.device.get_hand_target()


func _radius() -> float:
	return get_viewport().get_visible_rect().size.y * 0.25


func test_a_pointer_left_anywhere_steers_nothing() -> void:
	var size: Vector2 = get_viewport().get_visible_rect().size
	_motion(Vector2(size.x * 0.7, size.y * 0.9))
	assert_almost_eq(await _hand_after_frames(), Vector2.ZERO, 1e-3, "the hand stays centred")
	assert_false(Haptics.get_mouse_stick().held, "no stick to draw")


func test_dragging_with_the_button_held_steers_and_letting_go_centres() -> void:
	var grip: Vector2 = Vector2(300.0, 400.0)
	_motion(grip)
	_button(grip, true)
	_motion(grip + Vector2(_radius() * 0.5, -_radius() * 0.25))
	var hand: Vector2 = await _hand_after_frames()
	assert_almost_eq(hand, Vector2(0.5, -0.25), 0.02, "half right, a quarter up")
	var stick: HapticsMouseStick = Haptics.get_mouse_stick()
	assert_true(stick.held, "the game can draw it")
	assert_almost_eq(stick.origin, grip, 0.5, "gripped where the press began")
	assert_almost_eq(stick.deflection(), Vector2(0.5, -0.25), 0.02, "drawn as it steers")
	_motion(grip + Vector2(_radius() * 3.0, 0.0))
	assert_almost_eq((await _hand_after_frames()).length(), 1.0, 0.02, "at most full deflection")
	_button(grip + Vector2(_radius() * 3.0, 0.0), false)
	assert_almost_eq(await _hand_after_frames(), Vector2.ZERO, 1e-3, "let go: centred")
	assert_false(Haptics.get_mouse_stick().held)


func test_a_click_on_a_control_grips_nothing() -> void:
	var button: Button = Button.new()
	button.position = Vector2(100.0, 100.0)
	button.size = Vector2(200.0, 80.0)
	add_child_autofree(button)
	await get_tree().process_frame
	var on_button: Vector2 = Vector2(200.0, 140.0)
	_motion(on_button)
	_button(on_button, true)
	_motion(on_button + Vector2(_radius() * 0.8, 0.0))
	assert_almost_eq(await _hand_after_frames(), Vector2.ZERO, 1e-3, "the control took it")
	assert_false(Haptics.get_mouse_stick().held)


func test_the_keys_win_over_the_stick_and_an_autopilot_hides_it() -> void:
	var grip: Vector2 = Vector2(600.0, 300.0)
	_motion(grip)
	_button(grip, true)
	_motion(grip + Vector2(-_radius() * 0.6, 0.0))
	assert_lt((await _hand_after_frames()).x, -0.5, "the stick steers left")
	Input.action_press(&"move_right")
	assert_gt((await _hand_after_frames()).x, 0.5, "the key steers right over it")
	Input.action_release(&"move_right")
	Haptics.hand_follows_input = false
	assert_false(Haptics.get_mouse_stick().held, "nothing to draw while a script steers")
