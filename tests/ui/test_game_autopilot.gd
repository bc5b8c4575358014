extends TestSuite
## The game under the autopilot (a [LevelPilot], tests/drivers/), in process: it follows the
## level's path, prints the documented status line, ends after its time budget, and hands the
## simulated device's hand back to the mouse when it leaves.

const GAME_SCENE: PackedScene = preload("res://game/main/game.tscn")
const STATUS_PATTERN: String = (
	"^t=\\s*\\d+\\.\\ds servo=(\\d+ Hz|off) input=\\([+-]\\d\\.\\d\\d, [+-]\\d\\.\\d\\d\\) "
	+ "force=\\([+-]\\d+\\.\\d\\d, [+-]\\d+\\.\\d\\d\\) N \\|F\\|=\\d+\\.\\d\\d N contacts=\\d+$"
)

var _game: Game = null
var _pilot: LevelPilot = null


func before_each() -> void:
	_game = GAME_SCENE.instantiate() as Game
	_pilot = LevelPilot.new()
	_pilot.seconds = 1.0
	_pilot.print_status = false
	_game.pilot = _pilot
	add_child_autofree(_game)


func after_each() -> void:
	get_tree().paused = false


func test_the_level_is_level_1() -> void:
	assert_true(ResourceLoader.exists(Game.LEVEL_1_PATH), "the game has no fallback level")
	assert_eq(_game.level.scene_file_path, Game.LEVEL_1_PATH)


func test_the_autopilot_steers_toward_the_first_waypoint() -> void:
	var pilot: Autopilot = _pilot.autopilot
	if not assert_not_null(pilot):
		return
	assert_eq(pilot.path, _game.level.get_autopilot_path())
	var start: Vector2 = _game.player.global_position
	await wait_physics_frames(20)
	assert_false(_game.player.use_keyboard)
	if pilot.path.size() >= 2:
		var target: Vector2 = pilot.path[mini(pilot.index, pilot.path.size() - 1)]
		assert_lt(
			_game.player.global_position.distance_to(target),
			start.distance_to(target) + 1.0,
			"no farther from the waypoint than at the start"
		)
	else:
		assert_gt(_game.player.global_position.distance_to(start), 1.0, "it sweeps around")


func test_the_status_line_has_the_documented_shape() -> void:
	await wait_physics_frames(3)
	var pattern: RegEx = RegEx.create_from_string(STATUS_PATTERN)
	var line: String = _pilot.status_line()
	assert_not_null(pattern.search(line), line)
	assert_true(line.begins_with("t= 0."), line)


func test_the_run_ends_after_its_time_budget() -> void:
	var reasons: Array[String] = []
	_pilot.finished.connect(func(reason: String) -> void: reasons.append(reason))
	await wait_physics_frames(55)
	assert_eq(reasons, ["time"] as Array[String])
	assert_almost_eq(_game.elapsed, 1.0, 1e-4)


func test_reaching_the_goal_ends_the_run_without_the_goal_screen() -> void:
	var reasons: Array[String] = []
	_pilot.finished.connect(func(reason: String) -> void: reasons.append(reason))
	await wait_physics_frames(2)
	_game.level.goal_reached.emit()
	assert_eq(reasons, ["goal"] as Array[String])
	assert_false(_game.goal_screen.visible)
	assert_false(get_tree().paused)


func test_the_hand_goes_back_to_the_mouse_afterwards() -> void:
	var haptics: Node = get_node_or_null(^"/root/Haptics")
	if haptics == null or not (&"hand_follows_input" in haptics):
		skip("the Haptics autoload has no hand_follows_input")
		return
	assert_false(haptics.get(&"hand_follows_input"))
	remove_child(_game)
	assert_true(haptics.get(&"hand_follows_input"))
	_game.free()
