extends "res://tests/ui/tour/tour.gd"
## Walks through Haptic Battle Pong under a real display and saves a PNG of each moment,
## for looking at it (not a test: the runner skips this folder's files).
## [codeblock]
## DISPLAY=:N tools/godot --path . --rendering-driver opengl3 --audio-driver Dummy \
##     res://tests/ui/tour/pong_tour.tscn -- --out=/tmp/pong-shots
## [/codeblock]
## Shots: the menu with the Pong entry, the setup, a computer-vs-computer rally (court,
## ball and its shadow, paddles, avatars), the ball high up (the shadow's size and fade),
## a mine going off and its effect on the HUD, the gun and a bullet, beginner mode with
## the targets, the pause menu and the winner screen, then four computers on the square
## court (also in beginner mode).

const MAIN_SCENE: PackedScene = preload("res://game/main/main.tscn")

var _main: Main = null


func _ready() -> void:
	out = "user://pong-shots"
	super()


func _tour() -> void:
	_main = MAIN_SCENE.instantiate() as Main
	_main.read_command_line = false
	add_child(_main)
	await _shot("pong_menu", 1.0)
	_main.show_pong()
	await _shot("pong_preparing", 0.3)
	var pong: PongScreen = _main.get_screen() as PongScreen
	# Its buttons come once the court behind it is drawn (seconds on a first launch).
	while pong.setup.is_preparing():
		await get_tree().process_frame
	await _shot("pong_setup", 0.6)
	if not pong.is_running() and not PongServo.shared().is_available():
		print("no Pong renderer: ", pong.setup.get_message())
		get_tree().quit(0)
		return
	pong.start_match(PongMatch.Mode.DEMO, false)
	await _shot("pong_rally_3s", 3.0)
	await _shot("pong_rally_6s", 3.0)
	await _ball_high(pong)
	await _mine(pong)
	await _gun(pong)
	pong.pause_menu.open()
	await _shot("pong_pause", 0.5)
	pong.pause_menu.close()
	pong.winner_screen.show_winner("Computer 2", [0, 12] as Array[int])
	await _shot("pong_winner", 0.5)
	get_tree().paused = false
	_main.show_pong()
	pong = _main.get_screen() as PongScreen
	pong.start_match(PongMatch.Mode.VS_COMPUTER, false)
	await _device(pong)
	_main.show_pong()
	pong = _main.get_screen() as PongScreen
	pong.start_match(PongMatch.Mode.DEMO, true)
	await _shot("pong_beginner", 4.0)
	# Four computers on the square court, seen from player 0's side.
	_main.show_pong()
	pong = _main.get_screen() as PongScreen
	pong.players = 4
	pong.start_match(PongMatch.Mode.DEMO, false)
	await _shot("pong_four_players_3s", 3.0)
	await _shot("pong_four_players_6s", 3.0)
	_main.show_pong()
	pong = _main.get_screen() as PongScreen
	pong.players = 4
	pong.start_match(PongMatch.Mode.DEMO, true)
	await _shot("pong_four_players_beginner", 3.0)
	get_tree().quit(0)


# A lob high over the near half, shot at its top: the shadow grows and fades with height.
func _ball_high(pong: PongScreen) -> void:
	pong.match_node.auto_serve = false
	PongServo.shared().set_ball(Vector3(-0.7, 1.5, 1.2), Vector3(0.0, 2.4, 0.0))
	await _shot("pong_ball_high", 0.4)
	pong.match_node.auto_serve = true


# Player 0 on the simulated device: a ball dropped on its paddle (the contact force in the
# plot), then the opponent's heavy mine under it (the effect's steady force and countdown).
func _device(pong: PongScreen) -> void:
	var match_node: PongMatch = pong.match_node
	match_node.auto_serve = false
	(match_node.controllers[0] as PongHumanPlayer).reads_input = false
	await _shot("pong_vs_computer", 0.5)
	var paddle: Vector3 = match_node.snapshot.paddle_centers[0]
	PongServo.shared().set_ball(paddle + Vector3(0.0, 0.6, -0.05), Vector3.ZERO)
	await _shot("pong_device_contact_plot", 0.7)
	var avatar: Vector3 = match_node.avatar_of(0)
	for spot: Vector3 in [Vector3(-1.0, 0.0, -2.5), Vector3(avatar.x, 0.0, -avatar.z)]:
		var mine: PongMines.Mine = match_node.mines.place(1, spot, match_node.court)
		if mine != null:
			match_node.mine_placed.emit(mine)
	await _shot("pong_device_heavy_mine", 1.5)


# A mine of player 0 right under the far avatar: it goes off at the next update.
func _mine(pong: PongScreen) -> void:
	var match_node: PongMatch = pong.match_node
	var victim: Vector3 = match_node.avatar_of(1)
	var mine: PongMines.Mine = match_node.mines.place(
		0, Vector3(victim.x, 0.0, -victim.z), match_node.court
	)
	if mine != null:
		match_node.mine_placed.emit(mine)
	await _shot("pong_mine_exploding", 0.1)
	await _shot("pong_mine_effect_hud", 1.0)


func _gun(pong: PongScreen) -> void:
	var ai: PongAi = pong.match_node.controllers[0] as PongAi
	ai.fire_interval_s = 0.3
	var waited: float = 0.0
	while pong.match_node.bullets.flying.is_empty() and waited < 6.0:
		await get_tree().process_frame
		waited += get_process_delta_time()
	await _shot("pong_gun_bullet", 0.05)

# Software rendering under Xvfb is slow: a few frames pass after the wait so that the
# picture shows the state of its moment.
