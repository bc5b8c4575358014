extends TestSuite
## The 3D room from the main menu: its button opens it, Esc returns to the menu; a held arrow
## key walks the explorer through the simulated device (the keys move the hand on the ground
## plane, the probe feeds it back); and the autopilot walks it through the pool and up the
## ramp to the goal, felt all the way (the pool's drag, the ramp's tilted normal), with no
## engine error.

## Runs scenes for seconds: make check (--quick) leaves it out.
const SLOW := true

const MAIN_SCENE: PackedScene = preload("res://game/main/main.tscn")
## The autopilot walks about 22 m at up to 3 m/s: a minute is plenty on a loaded machine.
const GOAL_PATIENCE_FRAMES := 60 * 60

var _main: Main = null


func before_each() -> void:
	_main = MAIN_SCENE.instantiate() as Main
	_main.read_command_line = false
	add_child_autofree(_main)
	await wait_process_frames(2)


func after_each() -> void:
	Input.action_release(&"move_up")
	get_tree().paused = false


func test_the_menus_button_opens_the_room_and_escape_returns() -> void:
	(_main.get_screen() as MainMenu).room_3d_button.pressed.emit()
	var room: Room3D = _main.get_screen() as Room3D
	if not assert_not_null(room, "the 3D room button shows the room"):
		return
	assert_null(room.pilot, "the person steers")
	assert_false((_main.get_node(^"Background") as CanvasItem).visible)
	await wait_physics_frames(5)
	assert_gt(room.probe().frames_submitted, 0, "the probe sends frames")
	var escape: InputEventKey = InputEventKey.new()
	escape.keycode = KEY_ESCAPE
	escape.pressed = true
	Input.parse_input_event(escape)
	await wait_process_frames(2)
	assert_true(_main.get_screen() is MainMenu, "Esc returns to the menu")


func test_a_held_up_key_walks_the_explorer_away_from_the_camera() -> void:
	_main.start_room_3d()
	var room: Room3D = _main.get_screen() as Room3D
	await wait_physics_frames(10)
	var start: Vector3 = room.explorer.position
	# The project's hand actions (haptics/input/hand_actions): the arrows and WASD.
	Input.action_press(&"move_up")
	await wait_physics_frames(60)
	Input.action_release(&"move_up")
	assert_true(Haptics.game_3d, "the room's frames make the door 3D")
	var moved: Vector3 = room.explorer.position - start
	assert_lt(moved.z, -0.5, "forward is away from the camera (-z): moved %s" % moved)
	assert_lt(absf(moved.x), 0.2, "and straight on")


func test_the_autopilot_reaches_the_goal_through_the_pool_and_up_the_ramp() -> void:
	var pilot: Room3DAutopilot = Room3DAutopilot.new()
	_main.start_room_3d(pilot)
	var room: Room3D = _main.get_screen() as Room3D
	var felt: Dictionary[String, int] = {"wet": 0, "ramp": 0}
	var ramp_normal: Vector3 = Vector3(0.0, cos(deg_to_rad(14.0)), sin(deg_to_rad(14.0)))
	room.probe().frame_submitted.connect(
		func(frame: HapticFrame3D) -> void:
			felt["wet"] += 1 if frame.in_water else 0
			for contact: HapticContact3D in frame.contacts:
				felt["ramp"] += 1 if contact.normal.distance_to(ramp_normal) < 0.05 else 0
	)
	for frame: int in GOAL_PATIENCE_FRAMES:
		await get_tree().physics_frame
		if room.finished:
			break
	assert_true(room.finished, "the goal, at waypoint %d of %d" % [pilot.next, Room3D.PATH.size()])
	assert_gt(felt["wet"], 10, "waded through the pool")
	assert_gt(felt["ramp"], 10, "walked up the ramp, felt along its normal")
	print(
		(
			"room 3D: goal in %.1f s of game time, %d frames in water, %d on the ramp"
			% [room.elapsed, felt["wet"], felt["ramp"]]
		)
	)
