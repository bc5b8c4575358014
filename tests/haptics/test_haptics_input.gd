extends TestSuite
## What the Haptics autoload does with a game's input: which actions move the simulated hand
## (none, or names the game lacks, without an error per frame), feeding the device's input
## vector into a game's own actions for games that read Input.get_axis, and telemetry that
## stays off until someone drains it.

const FED: PackedStringArray = ["test_fed_left", "test_fed_right", "test_fed_up", "test_fed_down"]
const MOVE_ACTIONS: PackedStringArray = ["move_left", "move_right", "move_up", "move_down"]


## Notes the physics frame on which its _physics_process first sees [member action] pressed.
class PressWatcher:
	extends Node

	var action: String = ""
	var first_frame: int = -1

	func _physics_process(_delta: float) -> void:
		if first_frame < 0 and Input.is_action_pressed(action):
			first_frame = Engine.get_physics_frames()


## Notes the physics frame on which its _integrate_forces first sees [member action]
## pressed: the physics server calls it before any node's _physics_process.
class RigidWatcher:
	extends RigidBody2D

	var action: String = ""
	var first_frame: int = -1

	func _init() -> void:
		gravity_scale = 0.0
		can_sleep = false

	func _integrate_forces(_state: PhysicsDirectBodyState2D) -> void:
		if first_frame < 0 and Input.is_action_pressed(action):
			first_frame = Engine.get_physics_frames()


var _hand_actions: PackedStringArray = []
var _feed_actions: PackedStringArray = []
var _follows: bool = true
var _control_mode: StringName = &""


func before_each() -> void:
	_hand_actions = Haptics.hand_actions
	_feed_actions = Haptics.feed_actions
	_follows = Haptics.hand_follows_input
	_control_mode = Haptics.control_mode
	for action: String in FED:
		InputMap.add_action(action)


func after_each() -> void:
	Haptics.feed_actions = _feed_actions
	Haptics.hand_actions = _hand_actions
	Haptics.hand_follows_input = _follows
	Haptics.control_mode = _control_mode
	Haptics.device.set_hand_target(Vector2.ZERO)
	for action: String in FED:
		InputMap.erase_action(action)


func _physics_frames(count: int) -> void:
	for i: int in count:
		await get_tree().physics_frame


## Adds [param watchers] (each watching [code]FED[1][/code]) and holds the hand to the
## right with the feed set up but the keyboard driving the player: nothing is fed yet.
func _hold_right_unfed(watchers: Array[Node]) -> void:
	for watcher: Node in watchers:
		watcher.set(&"action", FED[1])
		add_child_autofree(watcher)
	Haptics.hand_follows_input = false
	Haptics.feed_actions = FED
	Haptics.control_mode = Haptics.CONTROL_KEYBOARD
	Haptics.device.set_hand_target(Vector2(1.0, 0.0))
	assert_true(await _wait_for_input(0.95), "the hand is to the right")


func _wait_for_input(at_least: float) -> bool:
	for i: int in 100:
		await get_tree().physics_frame
		if Haptics.get_input_vector().x >= at_least:
			return true
	return false


func test_the_hand_follows_the_projects_actions_and_none_is_allowed() -> void:
	var own: PackedStringArray = ProjectSettings.get_setting(Haptics.SETTING_HAND_ACTIONS)
	assert_eq(Haptics.hand_actions, own, "the project's setting")
	assert_eq(own, PackedStringArray(MOVE_ACTIONS), "this project's own actions")
	assert_ne(own, Haptics.DEFAULT_HAND_ACTIONS, "not the addon's default")
	Haptics.hand_actions = FED
	Input.action_press(FED[1])
	assert_true(await _wait_for_input(0.5), "the hand moved right with the named action")
	Input.action_release(FED[1])
	Haptics.hand_actions = PackedStringArray()
	Input.action_press(FED[1])
	await _physics_frames(10)
	assert_almost_eq(Haptics.get_input_vector(), Vector2.ZERO, 0.05, "no actions: no hand motion")
	Input.action_release(FED[1])


func test_actions_the_game_lacks_are_reported_once_not_every_frame() -> void:
	# A warning when they are named (the runner fails a test on any error, so a per-frame
	# error from polling them would fail this one).
	Haptics.hand_actions = ["test_fed_left", "test_fed_right", "no_such_up", "no_such_down"]
	Input.action_press(FED[1])
	assert_true(await _wait_for_input(0.5), "the actions that exist still move the hand")
	Input.action_release(FED[1])
	Haptics.hand_actions = ["test_fed_left", "test_fed_right", "", ""]  # no warning: none
	Input.action_press(FED[1])
	assert_true(await _wait_for_input(0.5), "empty names: left and right only")
	Input.action_release(FED[1])
	expect_error("give four actions")
	Haptics.hand_actions = ["test_fed_left"]
	assert_eq(Haptics.hand_actions.size(), 4, "refused: the previous actions stay")


func test_the_input_vector_is_fed_into_the_games_actions() -> void:
	Haptics.hand_follows_input = false
	Haptics.feed_actions = FED
	Haptics.device.set_hand_target(Vector2(1.0, 0.0))
	assert_true(await _wait_for_input(0.95), "the hand is to the right")
	await _physics_frames(5)
	var i: Vector2 = Haptics.get_input_vector()
	assert_almost_eq(Input.get_axis(FED[0], FED[1]), i.x, 0.05, "get_axis reads the device")
	assert_almost_eq(Input.get_action_strength(FED[1]), i.x, 0.05, "as the action's strength")
	assert_eq(Input.get_action_strength(FED[0]), 0.0)
	Haptics.control_mode = Haptics.CONTROL_KEYBOARD
	await _physics_frames(2)
	assert_eq(Input.get_action_strength(FED[1]), 0.0, "released in keyboard mode")


# The device's input once the hand has settled at [param target] (it follows the target
# through the simulated device's dynamics and the input mapping).
func _settled_input(target: Vector2) -> float:
	Haptics.device.set_hand_target(target)
	var previous: float = INF
	for i: int in 150:
		await get_tree().physics_frame
		var now: float = Haptics.get_input_vector().x
		if absf(now - previous) < 1e-4:
			break
		previous = now
	await _physics_frames(2)
	return Haptics.get_input_vector().x


func test_a_drift_is_no_press_and_a_deflection_keeps_its_strength() -> void:
	# A game that reads is_action_pressed (Godot's physics platformer) must not walk at full
	# speed because the hand drifted a little: the action is pressed past its deadzone, as a
	# stick's is, with the deflection as its strength.
	Haptics.hand_follows_input = false
	Haptics.feed_actions = FED
	var deadzone: float = InputMap.action_get_deadzone(FED[1])
	var drift: float = await _settled_input(Vector2(0.1, 0.0))
	assert_gt(drift, 0.03, "the hand drifted")
	assert_lt(drift, deadzone, "inside the action's deadzone")
	assert_false(Input.is_action_pressed(FED[1]), "a drift is no press")
	assert_eq(Input.get_action_strength(FED[1]), 0.0)
	var deflection: float = await _settled_input(Vector2(0.6, 0.0))
	assert_gt(deflection, deadzone, "past the deadzone")
	assert_true(Input.is_action_pressed(FED[1]), "pressed")
	assert_almost_eq(Input.get_action_strength(FED[1]), deflection, 0.01, "at its strength")
	drift = await _settled_input(Vector2(0.1, 0.0))
	assert_false(Input.is_action_pressed(FED[1]), "released inside the deadzone")


func test_fed_actions_arrive_before_the_games_physics_scripts() -> void:
	# The device turns the feed on within a physics tick, before the nodes' physics (at the
	# tree's physics_frame): a watcher that runs before the door sees the press one frame
	# after one that runs where game scripts do (priority 0): the door fed it in between.
	var early: PressWatcher = PressWatcher.new()
	early.process_physics_priority = -2000
	var game: PressWatcher = PressWatcher.new()
	await _hold_right_unfed([early, game])
	await get_tree().physics_frame
	Haptics.control_mode = Haptics.CONTROL_DEVICE
	await _physics_frames(2)
	assert_gt(game.first_frame, 0, "the game's script saw the press")
	assert_eq(early.first_frame, game.first_frame + 1, "the same frame it was fed")


func test_a_rigid_body_reading_input_in_integrate_forces_is_not_a_frame_late() -> void:
	# The device turns the feed on between two frames' physics (in the idle step), as a device
	# moving on its own does most of the time: a body's _integrate_forces runs first in the
	# next physics tick, before any _physics_process, and sees it on the same frame as the
	# game's scripts do.
	var rigid: RigidWatcher = RigidWatcher.new()
	var game: PressWatcher = PressWatcher.new()
	await _hold_right_unfed([rigid, game])
	await _physics_frames(2)
	assert_eq(game.first_frame, -1, "nothing is fed while the keyboard drives the player")
	await get_tree().process_frame
	Haptics.control_mode = Haptics.CONTROL_DEVICE
	await _physics_frames(3)
	assert_gt(game.first_frame, 0, "the game's _physics_process saw the press")
	assert_eq(rigid.first_frame, game.first_frame, "_integrate_forces saw it on the same frame")


func test_feeding_the_actions_that_move_the_hand_does_not_hold_them_down() -> void:
	# Keys move the simulated hand through the same actions the device is fed into: the
	# hand must read the keys alone, or the first press would never let go.
	Haptics.hand_follows_input = true
	Haptics.hand_actions = FED
	Haptics.feed_actions = FED
	var key: InputEventKey = InputEventKey.new()
	key.physical_keycode = KEY_F12
	InputMap.action_add_event(FED[1], key)
	key.pressed = true
	Input.parse_input_event(key)
	assert_true(await _wait_for_input(0.6), "the key moved the hand")
	key = key.duplicate()
	key.pressed = false
	Input.parse_input_event(key)
	var released: bool = false
	for i: int in 150:
		await get_tree().physics_frame
		if Haptics.get_input_vector().length() < 0.05:
			released = true
			break
	assert_true(released, "the hand came back when the key was released")
	await _physics_frames(2)
	assert_lt(Input.get_action_strength(FED[1]), 0.05, "and the fed action let go")


func test_a_key_held_down_survives_the_feed() -> void:
	# "The stronger wins": the device pushed the same way and back to the centre, or fed
	# and then switched off, never lets go of a key the player still holds.
	var key: InputEventKey = InputEventKey.new()
	key.physical_keycode = KEY_F9
	InputMap.action_add_event(FED[0], key)
	Haptics.hand_follows_input = false
	Haptics.feed_actions = FED
	var press: InputEventKey = key.duplicate() as InputEventKey
	press.pressed = true
	Input.parse_input_event(press)
	Input.flush_buffered_events()
	Haptics.device.set_hand_target(Vector2(-1.0, 0.0))
	await _physics_frames(30)
	assert_eq(Input.get_action_strength(FED[0]), 1.0, "the key's full strength while fed too")
	var lowest: float = 1.0
	Haptics.device.set_hand_target(Vector2.ZERO)
	for i: int in 60:
		await get_tree().physics_frame
		lowest = minf(lowest, Input.get_action_strength(FED[0]))
	assert_eq(lowest, 1.0, "the hand back at the centre: the key still holds the action")
	Haptics.device.set_hand_target(Vector2(-1.0, 0.0))
	await _physics_frames(30)
	Haptics.control_mode = Haptics.CONTROL_KEYBOARD
	await _physics_frames(2)
	assert_true(Input.is_action_pressed(FED[0]), "the feed switched off: the key still holds it")
	var release: InputEventKey = key.duplicate() as InputEventKey
	release.pressed = false
	Input.parse_input_event(release)
	Input.flush_buffered_events()
	await _physics_frames(2)
	assert_false(Input.is_action_pressed(FED[0]), "the key let go: released")


func test_telemetry_is_off_until_someone_drains_it() -> void:
	# A fresh door started as the autoload is (nothing an earlier suite drained or left).
	var haptics: HapticsTestKit.Door = add_child_autofree(HapticsTestKit.Door.new())
	haptics.feed_actions = PackedStringArray()
	haptics.hand_follows_input = false
	var capacity: int = HapticServoConstants.TELEMETRY_QUEUE_CAPACITY
	assert_false(haptics.servo.get_settings().telemetry.enabled, "off from the start")
	await _physics_frames(15)  # 0.3 s: 300 samples at 1 kHz if it were on
	assert_true(haptics.servo.is_running())
	# Stopped, so that no sample can come between draining's turning it on and its reading.
	haptics.servo.stop()
	assert_eq(haptics.servo.get_stats().telemetry_drops, 0, "nothing recorded, nothing to drop")
	assert_eq(haptics.servo.drain_telemetry(capacity).size(), 0)
	assert_true(haptics.servo.get_settings().telemetry.enabled, "draining turned it on")
	assert_true(haptics.servo.start())
	await _physics_frames(3)
	assert_gt(haptics.servo.drain_telemetry(16).size(), 0, "and samples arrive")
