extends "res://tests/ui/tour/tour.gd"
## The Pong screens issue 25 changed, under a real display, a PNG of each (not a test: the
## runner only runs test_*.gd files):
## [codeblock]
## DISPLAY=:N tools/godot --path . --rendering-driver opengl3 --audio-driver Dummy \
##     res://tests/pong/tour/pong_newcomer_tour.tscn -- --out=/tmp/shots
## [/codeblock]
## Shots: the setup (options before the start buttons), a match against the default
## computer with the ball resting against the near wall, a bullet in flight next to the
## ball, a plain mine going off (the status line), and beginner mode.

const MAIN_SCENE: PackedScene = preload("res://game/main/main.tscn")

var _main: Main = null


func _ready() -> void:
	out = "user://pong-newcomer-shots"
	super()


func _tour() -> void:
	_main = MAIN_SCENE.instantiate() as Main
	_main.read_command_line = false
	add_child(_main)
	_main.show_pong()
	await _shot("pong-setup", 0.8)
	var pong: PongScreen = _main.get_screen() as PongScreen
	if not PongServo.shared().is_available():
		print("no Pong renderer: ", pong.setup.get_message())
		get_tree().quit(1)
		return
	pong.start_match(PongMatch.Mode.VS_COMPUTER, false)
	var match_node: PongMatch = pong.match_node
	match_node.auto_serve = false
	(match_node.controllers[0] as PongHumanPlayer).reads_input = false
	var court: PongCourt = match_node.court
	# The ball at rest against the near wall, left, middle and right in turn.
	for x: float in [-1.2, 0.0, 1.2]:
		PongServo.shared().set_ball(
			Vector3(x, court.ball_radius, court.half_length - court.ball_radius), Vector3.ZERO
		)
		await _shot("pong-ball-near-wall-x%+.1f" % x, 0.4)
	# A bullet next to the ball.
	PongServo.shared().set_ball(Vector3(0.3, 1.0, 0.8), Vector3.ZERO)
	match_node.bullets.add(1, 0, Vector3(-0.2, 1.0, -0.5), Vector3(0.1, 0.0, 1.0))
	await _shot("pong-bullet-and-ball", 0.05)
	var mine: PongMines.Mine = PongMines.Mine.new(1, "none", Vector3(0.5, 0.0, 1.0))
	match_node.mine_exploded.emit(mine, 0)
	await _shot("pong-plain-mine-status", 0.2)
	_main.show_pong()
	pong = _main.get_screen() as PongScreen
	pong.start_match(PongMatch.Mode.VS_COMPUTER, true)
	await _shot("pong-beginner-vs-computer", 3.0)
	get_tree().quit(0)
