extends "res://tests/pong/pong_screen_suite.gd"
## The Pong screen as a player reaches it: the main menu's entry, the setup, a real-time
## match against the computer on the servo thread (the first serve, the HUD, a pause that
## holds the ball where it was), the spin paddle's colour, and the way back (Esc on the
## setup, the pause menu's Quit to menu) leaving the servo as it was.

## Runs scenes or processes for seconds: make check (--quick) leaves it out.
const SLOW := true

const MAIN_SCENE: PackedScene = preload("res://game/main/main.tscn")
const PONG_SCENE: PackedScene = preload("res://game/pong/ui/pong.tscn")
const WORLD_SCENE: PackedScene = preload("res://game/pong/view/pong_world.tscn")

var _main: Main = null
var _mode_before: StringName = &""


func before_each() -> void:
	_mode_before = Haptics.get_render_mode()
	_main = MAIN_SCENE.instantiate() as Main
	_main.read_command_line = false
	add_child_autofree(_main)
	await wait_process_frames(2)


func after_each() -> void:
	get_tree().paused = false


func test_the_menu_entry_opens_the_setup_and_escape_goes_back() -> void:
	var menu: MainMenu = _main.get_screen() as MainMenu
	menu.pong_button.pressed.emit()
	var pong: PongScreen = _main.get_screen() as PongScreen
	if not assert_not_null(pong, "the Pong screen"):
		return
	assert_true(pong.setup.visible, "it starts on the setup")
	assert_true(pong.setup.is_preparing(), "which first says it prepares the court")
	assert_false(pong.setup.vs_computer_button.is_visible_in_tree(), "with no button to start")
	assert_true(await _setup_offered(pong), "then offers its buttons")
	assert_false(pong.is_running())
	assert_true(pong.setup.vs_computer_button.has_focus(), "keyboard and gamepad start there")
	var cancel: InputEventAction = InputEventAction.new()
	cancel.action = &"ui_cancel"
	cancel.pressed = true
	Input.parse_input_event(cancel)
	await wait_process_frames(2)
	assert_true(_main.get_screen() is MainMenu, "Esc returns to the menu")


func test_the_network_lobby_starts_with_the_setup_court() -> void:
	for players: int in [4, 2]:
		# The main scene opens the lobby (it is above Pong).
		_main.show_pong()
		var pong: PongScreen = _main.get_screen() as PongScreen
		await _setup_offered(pong)
		pong.setup.four_players_check.button_pressed = players == 4
		pong.setup.network_button.pressed.emit()
		await wait_process_frames(1)
		var lobby: PongLobby = pong.find_children("*", "PongLobby", false, false).front()
		if not assert_not_null(lobby, "the lobby opens"):
			return
		assert_eq(lobby.chosen_seats(), players, "the setup's court is the lobby's seats")
		assert_false(pong.setup.visible, "the lobby replaces the setup")
		lobby.back_requested.emit()
		await wait_process_frames(2)
		assert_true(pong.setup.visible, "Back shows the setup again")


func test_a_real_time_match_serves_and_quitting_restores_the_servo() -> void:
	if not assert_true(PongServo.shared().is_available(), "the extension has the Pong renderer"):
		return
	(_main.get_screen() as MainMenu).pong_button.pressed.emit()
	var pong: PongScreen = _main.get_screen() as PongScreen
	await _setup_offered(pong)
	pong.setup.vs_computer_button.pressed.emit()
	if not assert_true(pong.is_running(), "the match runs"):
		return
	var match_node: PongMatch = pong.match_node
	assert_eq(Haptics.get_render_mode(), &"pong", "the servo renders Pong")
	assert_true(Haptics.servo.is_running(), "on its real-time thread")
	assert_false(Haptics.hand_follows_input, "the match moves the simulated hand")
	assert_eq(match_node.local_player, 0, "player 0 holds the (simulated) device")
	var moving: bool = await wait_until(
		func() -> bool: return match_node.snapshot.ball_velocity.length() > 0.5, 6.0
	)
	assert_true(moving, "the first serve puts the ball in play")
	assert_gt(match_node.referee.serves, 0)
	assert_has(pong.hud.get_panel(0).get_health_text(), str(match_node.rules.get_health(0)))
	# A ball at rest high up: the servo thread runs on while paused, the game puts it back.
	match_node.auto_serve = false
	PongServo.shared().set_ball(Vector3(-1.0, 2.0, 1.5), Vector3.ZERO)
	await wait_until(func() -> bool: return match_node.snapshot.ball_position.y > 1.9, 2.0)
	var caught: PongState = match_node.snapshot
	pong.pause_menu.open()
	assert_true(get_tree().paused)
	await wait_seconds(0.6)
	var resumed_at: float = PongServo.shared().get_state().time_s
	pong.pause_menu.close()
	await wait_process_frames(1)
	# Put back after resumed_at, it has fallen at most since then (the frame's length,
	# whatever the load); left alone it fell for the whole pause and bounces below 1.5 m.
	var now: PongState = PongServo.shared().get_state()
	var fall: float = now.time_s - resumed_at
	var lowest: float = (
		caught.ball_position.y
		+ minf(caught.ball_velocity.y, 0.0) * fall
		- 0.5 * match_node.court.gravity * fall * fall
		- 0.01
	)
	assert_gt(now.ball_position.y, lowest, "the ball is back where the pause caught it")
	pong.pause_menu.open()
	pong.pause_menu.quit_button.pressed.emit()
	await wait_process_frames(2)
	assert_true(_main.get_screen() is MainMenu, "Quit to menu")
	assert_eq(Haptics.get_render_mode(), _mode_before, "the previous renderer is back")
	assert_true(Haptics.hand_follows_input, "the hand follows the mouse again")


func test_a_ball_on_the_device_paddle_shows_in_the_force_plot() -> void:
	if not assert_true(PongServo.shared().is_available(), "the extension has the Pong renderer"):
		return
	var pong: PongScreen = add_child_autofree(PONG_SCENE.instantiate()) as PongScreen
	pong.start_match(PongMatch.Mode.VS_COMPUTER, false)
	var match_node: PongMatch = pong.match_node
	match_node.auto_serve = false
	(match_node.controllers[0] as PongHumanPlayer).reads_input = false
	await wait_seconds(0.3)
	var plot: ForcePlot = pong.hud.get_plot()
	assert_lt(plot.buffer.max_value(), 0.05, "nothing felt before")
	var paddle: Vector3 = match_node.snapshot.paddle_centers[0]
	PongServo.shared().set_ball(paddle + Vector3(0.0, 0.6, -0.05), Vector3.ZERO)
	var felt: bool = await wait_until(func() -> bool: return plot.buffer.max_value() > 0.3, 3.0)
	assert_true(felt, "the contact's force reaches the plot")


func test_the_spin_paddle_changes_colour() -> void:
	var paddle: PongPaddleView = PongPaddleView.new()
	add_child_autofree(paddle)
	paddle.setup(0.2, PongView.PLAYER_COLORS[0])
	var plain: Color = paddle.get_color()
	paddle.show_modes(true, false, false)
	assert_ne(paddle.get_color(), plain, "spin on: another colour")
	assert_almost_eq(Color(paddle.get_color(), 1.0), Color(PongPaddleView.SPIN_COLOR, 1.0), 1e-3)
	paddle.show_modes(false, false, false)
	assert_almost_eq(paddle.get_color(), plain, 1e-3, "and back")


func test_the_setup_shows_the_chosen_court_and_the_match_replaces_it() -> void:
	if not assert_true(PongServo.shared().is_available(), "the extension has the Pong renderer"):
		return
	(_main.get_screen() as MainMenu).pong_button.pressed.emit()
	var pong: PongScreen = _main.get_screen() as PongScreen
	var world: PongView = pong.world
	assert_eq(_count(world, "PongAvatarView"), 0, "the setup's own frame first")
	# Then the court, and a frame each: a mine, its flash, a bullet; then the buttons.
	var shown: Array[String] = []
	for frame: int in 8:
		await wait_process_frames(1)
		if shown.is_empty() and _count(world, "PongAvatarView") == 2:
			shown.append("court")
		var mines: Array[Node] = world.find_children("*", "PongMineView", true, false)
		if not mines.is_empty():
			shown.append("flash" if (mines[0] as PongMineView).is_exploding() else "mine")
		if world.get_node("Bullets").get_child_count() > 0:
			shown.append("bullet")
	assert_eq(shown.front(), "court", "the court first, behind the setup (%s)" % [shown])
	assert_has(shown, "mine", "a mine drawn once behind the setup")
	assert_has(shown, "flash", "and a mine's flash")
	assert_has(shown, "bullet", "and a bullet")
	assert_false(pong.setup.is_preparing(), "then the setup offers its buttons")
	pong.setup.four_players_check.button_pressed = true
	await wait_process_frames(2)
	assert_eq(_count(world, "PongAvatarView"), 4, "ticking four players shows their court")
	pong.setup.four_players_check.button_pressed = false
	# The network lobby covers the setup and its court: a match it starts draws its own.
	pong.setup.network_button.pressed.emit()
	await wait_process_frames(1)
	var lobby: PongLobby = pong.find_children("*", "PongLobby", false, false).front()
	assert_eq(_count(world, "PongAvatarView"), 0, "no court behind the lobby")
	assert_eq(world.get_node("Court").get_child_count(), 0, "not even its floor")
	lobby.back_requested.emit()
	await wait_process_frames(2)
	assert_eq(_count(world, "PongAvatarView"), 2, "Back: the setup's court again")
	pong.setup.vs_computer_button.pressed.emit()
	await wait_process_frames(2)
	assert_true(pong.is_running(), "the match runs")
	assert_eq(_count(world, "PongAvatarView"), 2, "the match's players replace the preview's")
	assert_not_null(world.get_node_or_null("Avatar1"), "under their own names")
	assert_eq(_count(world, "PongMineView"), 0, "no mine before one is placed")


func _count(world: PongView, type: String) -> int:
	return world.find_children("*", type, true, false).size()


func test_each_seat_sees_the_court_through_its_own_back_wall() -> void:
	var court: PongCourt = PongCourt.from_settings(PongSettings.new())
	for viewer: int in 2:
		var world: PongView = add_child_autofree(WORLD_SCENE.instantiate()) as PongView
		world.build(court, 0.3, true, viewer)
		var far: float = court.back_wall_z(PongCourt.opponent_of(viewer))
		var glass: Node3D = world.get_node("Court/FarWall") as Node3D
		assert_almost_eq(glass.position.z, far, 1e-4, "seat %d: glass on the far wall" % viewer)
		var own: Node3D = world.get_node("Court/Target%d" % viewer) as Node3D
		var other: Node3D = world.get_node("Court/Target%d" % (1 - viewer)) as Node3D
		assert_lt(own.position.y, 0.01, "seat %d: its own target a strip on the floor" % viewer)
		assert_lt(absf(own.position.z), court.half_length, "seat %d: in front of its wall" % viewer)
		assert_gt(other.position.y, 0.1, "seat %d: the other's target on its wall" % viewer)
		for post: Node in world.get_node("Court").find_children("TargetPost*", "", false, false):
			assert_lt(absf((post as Node3D).position.z - far), 0.05, "seat %d: posts far" % viewer)
