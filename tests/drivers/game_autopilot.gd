extends Node
## The side-scroller played by its autopilot ([LevelPilot]) instead of a person: the real main
## scene, straight into level 1, one status line per second of game time, quitting with exit
## code 0 at the goal or after [code]--autopilot-seconds=N[/code] (default 5; 0: only at the
## goal). What [code]make play[/code] runs without a display, and what the windowed test, the
## test without the extension and the main scene's test run.
## [codeblock]
## tools/godot --headless --path . res://tests/drivers/game_autopilot.tscn -- \
##     [--autopilot-seconds=N]
## [/codeblock]

const MAIN_SCENE: PackedScene = preload("res://game/main/main.tscn")

var _pilot: LevelPilot = null


func _ready() -> void:
	var pilot: LevelPilot = LevelPilot.new()
	_pilot = pilot
	for arg: String in OS.get_cmdline_user_args():
		if arg.begins_with("--autopilot-seconds="):
			pilot.seconds = arg.get_slice("=", 1).to_float()
	pilot.finished.connect(_on_finished)
	var main: Main = MAIN_SCENE.instantiate() as Main
	main.read_command_line = false
	add_child(main)
	print("Autopilot on: %s; level %s" % [Main.system_line(), Game.LEVEL_1_PATH])
	main.start_game(pilot)


func _on_finished(reason: String) -> void:
	if reason == "time":
		# Without it the run just stopped, and a newcomer took the game for broken.
		print(
			(
				(
					"Autopilot: stopped after %.0f s of play, as asked "
					+ "(--autopilot-seconds=N plays N seconds, 0 until the goal)."
				)
				% _pilot.seconds
			)
		)
	else:
		print("Autopilot: the goal reached; done.")
	CleanExit.quit(0)
