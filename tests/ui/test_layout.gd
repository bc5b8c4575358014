extends TestSuite
## Every screen a person meets, laid out at the window sizes players use (a small laptop, the
## default window, a full-HD screen): nothing off the screen, no two controls over each
## other, no text cut off, no text under 12 px (tests/ui/layout_check.gd).

const LayoutCheck := preload("res://tests/ui/layout_check.gd")
const SIZES: Array[Vector2i] = [Vector2i(1024, 600), Vector2i(1280, 720), Vector2i(1920, 1080)]


# The screen [param scene] in a viewport of [param size], prepared by [param prepare] (which
# opens or fills it as the game does), laid out; returns what a person would see wrong.
func _check(scene: String, size: Vector2i, prepare: Callable = Callable()) -> PackedStringArray:
	var viewport: SubViewport = SubViewport.new()
	viewport.size = size
	add_child_autofree(viewport)
	var screen: Node = (load(scene) as PackedScene).instantiate()
	viewport.add_child(screen)
	if prepare.is_valid():
		prepare.call(screen)
	await wait_process_frames(4)
	var found: PackedStringArray = LayoutCheck.problems(screen, Vector2(size))
	viewport.queue_free()
	return found


func _check_everywhere(scene: String, prepare: Callable = Callable()) -> void:
	for size: Vector2i in SIZES:
		var found: PackedStringArray = await _check(scene, size, prepare)
		assert_eq(found, PackedStringArray(), "%s at %s" % [scene.get_file(), size])


func test_the_main_menu() -> void:
	await _check_everywhere("res://game/ui/main_menu.tscn")


func test_the_settings_screen() -> void:
	await _check_everywhere("res://game/common/ui/settings_screen.tscn")


func test_the_pause_menu() -> void:
	await _check_everywhere(
		"res://game/common/ui/pause_menu.tscn", func(menu: Node) -> void: menu.call(&"open")
	)
	get_tree().paused = false


func test_the_goal_screen() -> void:
	await _check_everywhere(
		"res://game/ui/goal_screen.tscn",
		func(goal: Node) -> void: (goal as GoalScreen).show_result(83.4, 7, 12)
	)
	get_tree().paused = false


func test_the_level_hud_compact_and_lab_view() -> void:
	for view: Hud.View in [Hud.View.COMPACT, Hud.View.LAB]:
		var prepare: Callable = func(hud: Node) -> void:
			(hud as Hud).live = false
			(hud as Hud).view = view
		await _check_everywhere("res://game/ui/hud.tscn", prepare)


func test_the_pong_setup_and_lobby() -> void:
	await _check_everywhere("res://game/pong/ui/pong_setup.tscn")
	await _check_everywhere("res://game/pong/net/ui/pong_lobby.tscn")


func test_the_pong_hud_and_winner_screen() -> void:
	var titles: Array[String] = ["You · device", "Computer"]
	var colors: Array[Color] = [Color.DODGER_BLUE, Color.ORANGE]
	await _check_everywhere(
		"res://game/pong/ui/pong_hud.tscn",
		func(hud: Node) -> void: (hud as PongHud).setup(titles, colors, 99, 10.0, false)
	)
	var health: Array[int] = [12, 0]
	await _check_everywhere(
		"res://game/pong/ui/pong_winner_screen.tscn",
		func(screen: Node) -> void: (screen as PongWinnerScreen).show_winner("Ada", health, false)
	)


func test_the_study_screens() -> void:
	await _check_everywhere("res://game/study/screens/start_screen.tscn")
	await _check_everywhere(
		"res://game/study/screens/rating_screen.tscn",
		func(screen: Node) -> void: screen.call(&"setup", "Method 1 of 3")
	)
	await _check_everywhere(
		"res://game/study/screens/final_screen.tscn",
		func(screen: Node) -> void: screen.call(&"setup", PackedStringArray(["a", "b", "c"]))
	)
	await _check_everywhere(
		"res://game/study/screens/message_screen.tscn",
		func(screen: Node) -> void:
			screen.call(&"show_message", "Thank you!", "The session is complete.")
	)
