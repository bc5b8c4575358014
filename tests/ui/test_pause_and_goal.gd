extends TestSuite
## One run of the level: the pause action pauses the tree and shows the menu (which keeps
## processing while the level does not), Resume, Settings over the game and back, and the
## goal screen with time and items.

const GAME_SCENE: PackedScene = preload("res://game/main/game.tscn")
## The smallest level: these tests are about the flow, not the world.
const ROOM_SCENE: PackedScene = preload("res://tests/support/room.tscn")

var _game: Game = null


func before_each() -> void:
	_game = GAME_SCENE.instantiate() as Game
	_game.level_scene = ROOM_SCENE
	add_child_autofree(_game)
	await wait_physics_frames(2)


func after_each() -> void:
	get_tree().paused = false


func test_the_pause_action_toggles_the_pause() -> void:
	assert_false(get_tree().paused)
	_push_action(&"pause")
	assert_true(get_tree().paused)
	assert_true(_game.pause_menu.is_open())
	_push_action(&"pause")
	assert_false(get_tree().paused)
	assert_false(_game.pause_menu.is_open())


func test_only_the_menus_process_while_paused() -> void:
	_push_action(&"pause")
	assert_true(_game.pause_menu.can_process())
	assert_true(_game.goal_screen.can_process())
	assert_false(_game.level.can_process(), "the level stops")
	assert_false(_game.player.can_process())
	assert_false(_game.hud.can_process(), "the HUD freezes with the game")
	var clock: float = _game.elapsed
	await wait_process_frames(5)
	assert_eq(_game.elapsed, clock, "game time stands still")


func test_resume_unpauses() -> void:
	_game.pause_menu.open()
	await wait_process_frames(1)
	assert_true(_game.pause_menu.resume_button.has_focus())
	_game.pause_menu.resume_button.pressed.emit()
	assert_false(get_tree().paused)
	assert_false(_game.pause_menu.visible)


func test_settings_show_over_the_paused_game_and_close_back_to_the_menu() -> void:
	_game.pause_menu.open()
	_game.pause_menu.settings_button.pressed.emit()
	var screen: SettingsScreen = _game.pause_menu.get_settings_screen()
	if not assert_not_null(screen):
		return
	assert_true(screen.is_visible_in_tree())
	assert_true(screen.can_process())
	await wait_process_frames(1)
	_push_action(&"ui_cancel")
	assert_null(_game.pause_menu.get_settings_screen(), "Escape closes the settings")
	assert_true(_game.pause_menu.is_open(), "and leaves the pause menu")
	assert_true(get_tree().paused)


func test_quit_to_menu_is_asked_for_unpaused() -> void:
	var asked: Array[bool] = [false]
	_game.menu_requested.connect(func() -> void: asked[0] = true)
	_game.pause_menu.open()
	_game.pause_menu.quit_button.pressed.emit()
	assert_true(asked[0])
	assert_false(get_tree().paused)


func test_the_goal_shows_time_and_items_and_stops_the_clock() -> void:
	await wait_physics_frames(25)
	_game.level.item_collected.emit(2, 5)
	_game.level.goal_reached.emit()
	assert_true(_game.finished)
	assert_true(_game.goal_screen.visible)
	assert_true(get_tree().paused)
	assert_eq(_game.goal_screen.get_items_text(), "2 / 5")
	assert_eq(_game.goal_screen.get_time_text(), GoalScreen.format_time(_game.elapsed))
	assert_gt(_game.elapsed, 0.4)
	_push_action(&"pause")
	assert_false(_game.pause_menu.is_open(), "no pause menu over the goal screen")


func test_time_formatting() -> void:
	assert_eq(GoalScreen.format_time(0.0), "00:00.0")
	assert_eq(GoalScreen.format_time(83.46), "01:23.4")
	assert_eq(GoalScreen.format_time(3600.0), "60:00.0")
	assert_eq(GoalScreen.format_items(3, -1), "3")


func _push_action(action: StringName) -> void:
	var event: InputEventAction = InputEventAction.new()
	event.action = action
	event.pressed = true
	get_viewport().push_input(event)
