extends TestSuite
## The main scene's screens, driven as a player would: the title screen's buttons (pressed
## with pressed.emit()), keyboard focus, Settings and the maze study and back, Play, the pause
## menu's Quit to menu, and the goal screen's Play again / Menu.

const MAIN_SCENE: PackedScene = preload("res://game/main/main.tscn")
const MENU_SCENE: PackedScene = preload("res://game/ui/main_menu.tscn")

var _main: Main = null


func before_each() -> void:
	_main = MAIN_SCENE.instantiate() as Main
	_main.read_command_line = false
	add_child_autofree(_main)
	await wait_process_frames(2)


func after_each() -> void:
	get_tree().paused = false


func test_the_title_screen_comes_first_with_play_focused() -> void:
	var menu: MainMenu = _main.get_screen() as MainMenu
	if not assert_not_null(menu, "the first screen is the main menu"):
		return
	assert_eq(menu.play_button.text, "Play")
	assert_eq(menu.room_3d_button.text, "3D room")
	assert_eq(menu.drive_button.text, "Drive")
	assert_eq(menu.pong_button.text, "Haptic Battle Pong")
	assert_eq(menu.maze_button.text, "Maze study")
	assert_eq(menu.settings_button.text, "Settings")
	assert_eq(menu.quit_button.text, "Quit")
	assert_true(menu.play_button.has_focus(), "keyboard and gamepad start on Play")
	assert_true((_main.get_node(^"Background") as CanvasItem).visible)


func test_the_arrow_keys_move_the_focus_through_the_buttons() -> void:
	var menu: MainMenu = _main.get_screen() as MainMenu
	_press_key(KEY_DOWN)
	assert_true(menu.room_3d_button.has_focus())
	_press_key(KEY_RIGHT)
	assert_true(menu.drive_button.has_focus(), "the drive sits beside the 3D room")
	_press_key(KEY_DOWN)
	assert_true(menu.pong_button.has_focus())
	_press_key(KEY_DOWN)
	assert_true(menu.maze_button.has_focus())
	_press_key(KEY_DOWN)
	assert_true(menu.settings_button.has_focus())
	_press_key(KEY_DOWN)
	assert_true(menu.quit_button.has_focus())
	_press_key(KEY_UP)
	assert_true(menu.settings_button.has_focus())


func test_drive_opens_the_drive_and_escape_returns_to_the_menu() -> void:
	(_main.get_screen() as MainMenu).drive_button.pressed.emit()
	await wait_process_frames(2)
	var drive: DriveScene = _main.get_screen() as DriveScene
	if not assert_not_null(drive, "Drive shows the drive"):
		return
	assert_false((_main.get_node(^"Background") as CanvasItem).visible, "the 3D scene shows")
	_push_action(&"ui_cancel")
	await wait_process_frames(1)
	assert_true(_main.get_screen() is MainMenu, "Esc returns to the menu")


func test_settings_opens_and_back_returns_to_the_menu() -> void:
	var menu: MainMenu = _main.get_screen() as MainMenu
	menu.settings_button.pressed.emit()
	var screen: SettingsScreen = _main.get_screen() as SettingsScreen
	if not assert_not_null(screen, "Settings shows the settings screen"):
		return
	await wait_process_frames(1)
	assert_true(screen.device_option.has_focus())
	assert_gt(screen.device_option.item_count, 0)
	screen.back_button.pressed.emit()
	assert_true(_main.get_screen() is MainMenu, "Back returns to the menu")


func test_escape_leaves_the_settings_screen() -> void:
	(_main.get_screen() as MainMenu).settings_button.pressed.emit()
	await wait_process_frames(1)
	_push_action(&"ui_cancel")
	assert_true(_main.get_screen() is MainMenu)


func test_maze_study_opens_the_study_and_back_returns_to_the_menu() -> void:
	var menu: MainMenu = _main.get_screen() as MainMenu
	menu.maze_button.pressed.emit()
	var study: StudyRunner = _main.get_screen() as StudyRunner
	if not assert_not_null(study, "Maze study opens the study"):
		return
	assert_true(study.get_screen() is StartScreen, "the study starts on its start screen")
	(study.get_screen() as StartScreen).back_button.pressed.emit()
	await wait_process_frames(2)
	assert_true(_main.get_screen() is MainMenu, "Back returns to the title screen")


func test_quit_asks_to_quit() -> void:
	var menu: MainMenu = add_child_autofree(MENU_SCENE.instantiate()) as MainMenu
	var asked: Array[bool] = [false]
	menu.quit_requested.connect(func() -> void: asked[0] = true)
	menu.quit_button.pressed.emit()
	assert_true(asked[0])


func test_play_starts_the_level_with_its_hud() -> void:
	(_main.get_screen() as MainMenu).play_button.pressed.emit()
	var game: Game = _main.get_screen() as Game
	if not assert_not_null(game, "Play shows the game"):
		return
	assert_not_null(game.level)
	assert_not_null(game.player)
	assert_not_null(game.hud)
	assert_null(game.pilot, "the person steers")
	assert_false((_main.get_node(^"Background") as CanvasItem).visible)
	await wait_physics_frames(5)
	assert_gt(game.elapsed, 0.0, "the clock runs")


func test_quit_to_menu_from_the_pause_menu() -> void:
	(_main.get_screen() as MainMenu).play_button.pressed.emit()
	var game: Game = _main.get_screen() as Game
	game.pause_menu.open()
	assert_true(get_tree().paused)
	game.pause_menu.quit_button.pressed.emit()
	assert_false(get_tree().paused, "the menu is not left paused")
	assert_true(_main.get_screen() is MainMenu)


func test_the_goal_screen_offers_play_again_and_menu() -> void:
	(_main.get_screen() as MainMenu).play_button.pressed.emit()
	var game: Game = _main.get_screen() as Game
	await wait_physics_frames(3)
	game.level.goal_reached.emit()
	assert_true(game.goal_screen.visible)
	assert_true(get_tree().paused)
	game.goal_screen.play_again_button.pressed.emit()
	var again: Game = _main.get_screen() as Game
	assert_not_null(again, "Play again starts a new run")
	assert_ne(again, game)
	assert_false(get_tree().paused)
	again.level.goal_reached.emit()
	again.goal_screen.menu_button.pressed.emit()
	assert_true(_main.get_screen() is MainMenu)
	assert_false(get_tree().paused)


func _press_key(keycode: Key) -> void:
	var event: InputEventKey = InputEventKey.new()
	event.keycode = keycode
	event.physical_keycode = keycode
	event.pressed = true
	get_viewport().push_input(event)
	event = event.duplicate() as InputEventKey
	event.pressed = false
	get_viewport().push_input(event)


func _push_action(action: StringName) -> void:
	var event: InputEventAction = InputEventAction.new()
	event.action = action
	event.pressed = true
	get_viewport().push_input(event)
