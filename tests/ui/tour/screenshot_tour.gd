extends "res://tests/ui/tour/tour.gd"
## Walks through every screen of the game under a real display and saves a PNG of each,
## for looking at the UI (not a test: the runner skips this folder's files).
## [codeblock]
## DISPLAY=:N tools/godot --path . --rendering-driver opengl3 --audio-driver Dummy \
##     res://tests/ui/tour/screenshot_tour.tscn -- --out=/tmp/shots [--game-seconds=4]
## [/codeblock]

const MAIN_SCENE: PackedScene = preload("res://game/main/main.tscn")

var _game_seconds: PackedFloat32Array = PackedFloat32Array([3.0])


func _option(arg: String) -> void:
	if arg.begins_with("--game-seconds="):
		_game_seconds.clear()
		for part: String in arg.get_slice("=", 1).split(","):
			_game_seconds.append(part.to_float())


func _tour() -> void:
	var main: Node = MAIN_SCENE.instantiate()
	main.set(&"read_command_line", false)
	add_child(main)
	await _shot("menu", 1.5)
	main.call(&"show_settings")
	await _shot("settings", 0.8)
	main.call(&"show_maze")
	await _shot("maze", 0.8)
	var main_scene: Main = main as Main
	var pilot: LevelPilot = LevelPilot.new()
	pilot.seconds = 0.0
	main_scene.start_game(pilot)
	var game: Game = main_scene.get_screen() as Game
	var waited: float = 0.0
	for seconds: float in _game_seconds:
		await _shot("game_%04.1fs" % seconds, seconds - waited)
		waited = seconds
	await _demo_forces(game.hud)
	game.pause_menu.open()
	await _shot("pause", 0.6)
	game.pause_menu.open_settings()
	await _shot("pause_settings", 0.6)
	game.pause_menu.close()
	game.goal_screen.show_result(83.4, 3, 5)
	await _shot("goal", 0.6)
	get_tree().paused = false
	get_tree().quit(0)


# Feeds the HUD a made-up contact sequence (a bump, then resting under a crate on a slope,
# then water) so the arrows and the plot show something even without a probe.
func _demo_forces(hud: Hud) -> void:
	hud.live = false
	var start: int = Time.get_ticks_msec()
	while Time.get_ticks_msec() - start < 3500:
		var t: float = (Time.get_ticks_msec() - start) / 1000.0
		var impact: float = 2.6 * exp(-t * 6.0) * sin(t * 120.0) if t < 1.0 else 0.0
		var n: Vector2 = Vector2(-0.6, -0.8)
		var forces: Dictionary[String, Vector2] = {
			"normal": n * 1.4,
			"friction": Vector2(0.8, -0.6) * 0.5,
			"weight": Vector2(0.0, 0.7) if t > 1.5 else Vector2.ZERO,
			"drag": Vector2(-0.35, 0.1) if t > 2.5 else Vector2.ZERO,
			"inertia": Vector2(0.0, 0.3) if t > 2.5 else Vector2.ZERO,
			"impact": n * impact,
		}
		var total: Vector2 = Vector2.ZERO
		for force: Vector2 in forces.values():
			total += force
		forces["total"] = total
		hud.show_forces(HapticsTestKit.forces_of(forces))
		await get_tree().process_frame
	await _shot("hud_forces", 0.0)
	hud.live = true
