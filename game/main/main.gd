class_name Main
extends Node
## Entry scene: the main menu and the screens it leads to (Play, Haptic Battle Pong, Maze
## study, Settings).
##
## On a machine without a display, or with [code]-- --autopilot[/code], it skips the menu
## and plays level 1 under the [Autopilot], printing one status line per second, and quits
## with exit code 0 at the goal or after [code]--autopilot-seconds=N[/code] (default 5).
## With [code]-- --pong-demo[/code] it plays a computer-vs-computer Pong match instead,
## the servo stepped by the game (faster than real time), each player starting with
## [code]--pong-health=N[/code] (default [constant PONG_DEMO_HEALTH]), with
## [code]--pong-players=4[/code] four computers on the square court (default 2), and
## prints the winner and the simulated/wall time ratio.

const MENU_SCENE: PackedScene = preload("res://game/ui/main_menu.tscn")
const SETTINGS_SCENE: PackedScene = preload("res://game/common/ui/settings_screen.tscn")
## The maze user study.
const STUDY_SCENE: PackedScene = preload("res://game/study/session/study.tscn")
## One run of a level.
const GAME_SCENE: PackedScene = preload("res://game/main/game.tscn")
## Haptic Battle Pong.
const PONG_SCENE: PackedScene = preload("res://game/pong/ui/pong.tscn")
## Networked Pong's lobby, over the Pong setup.
const PONG_LOBBY_SCENE: PackedScene = preload("res://game/pong/net/ui/pong_lobby.tscn")
## Health of each player in the headless Pong demo: a short match.
const PONG_DEMO_HEALTH: int = 15

## Whether [method _ready] looks at the display and the command line to start the
## autopilot (tests turn it off, then drive the screens themselves).
@export var detect_autopilot: bool = true
## Game seconds the autopilot runs (0: until the goal); [code]--autopilot-seconds=N[/code].
@export var autopilot_seconds: float = 5.0

var _screen: Node = null

@onready var _background: MenuBackground = $Background


func _ready() -> void:
	if not detect_autopilot:
		show_menu()
		return
	var args: PackedStringArray = OS.get_cmdline_user_args()
	var pong_health: int = PONG_DEMO_HEALTH
	var pong_players: int = 2
	for arg: String in args:
		if arg.begins_with("--autopilot-seconds="):
			autopilot_seconds = arg.get_slice("=", 1).to_float()
		elif arg.begins_with("--pong-health="):
			pong_health = maxi(1, arg.get_slice("=", 1).to_int())
		elif arg.begins_with("--pong-players="):
			pong_players = 4 if arg.get_slice("=", 1).to_int() == 4 else 2
	if PongNetCli.wants(args):
		_background.visible = DisplayServer.get_name() != "headless"
		add_child(PongNetCli.new())
		return
	if args.has("--pong-demo"):
		start_pong_demo(pong_health, pong_players)
		return
	var headless: bool = DisplayServer.get_name() == "headless"
	if headless or args.has("--autopilot"):
		print(
			(
				"Autopilot on (%s): %s; %d device(s) found; %s; level %s"
				% [
					"no display" if headless else "--autopilot",
					Haptics.get_version(),
					Haptics.device.list_present().size(),
					MainMenu.device_status_text(),
					Game.default_level_path(),
				]
			)
		)
		start_game(true)
	else:
		show_menu()


## The screen showing now (a [MainMenu], [SettingsScreen], [StudyRunner] or [Game]).
func get_screen() -> Node:
	return _screen


func show_menu() -> void:
	var menu: MainMenu = _switch_to(MENU_SCENE) as MainMenu
	menu.play_requested.connect(start_game.bind(false))
	menu.pong_requested.connect(show_pong)
	menu.maze_requested.connect(show_maze)
	menu.settings_requested.connect(show_settings)
	menu.quit_requested.connect(_on_quit_requested)


## Shows the settings screen; Back returns to the title screen.
func show_settings() -> void:
	var screen: SettingsScreen = _switch_to(SETTINGS_SCENE) as SettingsScreen
	screen.closed.connect(show_menu)


## Opens the maze user study; leaving it returns to the title screen.
func show_maze() -> void:
	var study: StudyRunner = _switch_to(STUDY_SCENE) as StudyRunner
	study.closed.connect(show_menu)


## Opens Haptic Battle Pong on its setup; leaving it returns to the title screen.
func show_pong() -> void:
	_switch_to_node(_new_pong())


## A computer-vs-computer match with the servo stepped by the game, printing its result
## and quitting when it is over.
func start_pong_demo(health: int, players: int = 2) -> void:
	var pong: PongScreen = PONG_SCENE.instantiate() as PongScreen
	pong.skip_setup = true
	pong.mode = PongMatch.Mode.DEMO
	pong.stepped = true
	pong.start_health = health
	pong.players = players
	pong.quit_when_over = true
	print("Pong demo: %d computers, health %d, stepped servo" % [players, health])
	_switch_to_node(pong)


## Starts a run of the level, under the autopilot when [param with_autopilot].
func start_game(with_autopilot: bool = false) -> void:
	var game: Game = GAME_SCENE.instantiate() as Game
	game.autopilot = with_autopilot
	game.autopilot_seconds = autopilot_seconds
	game.menu_requested.connect(show_menu)
	game.restart_requested.connect(start_game.bind(with_autopilot))
	game.autopilot_finished.connect(_on_autopilot_finished)
	_switch_to_node(game)


func _switch_to(scene: PackedScene) -> Node:
	var node: Node = scene.instantiate()
	_switch_to_node(node)
	return node


func _switch_to_node(node: Node) -> void:
	get_tree().paused = false
	if _screen != null:
		remove_child(_screen)
		_screen.queue_free()
	_screen = node
	_background.visible = not (node is Game or node is PongScreen)
	add_child(node)


# Play again: a new Pong screen with the same settings, straight into the match.
func _replay_pong(previous: PongScreen) -> void:
	var pong: PongScreen = _new_pong()
	pong.skip_setup = true
	pong.mode = previous.mode
	pong.beginner = previous.beginner
	pong.start_health = previous.start_health
	pong.stepped = previous.stepped
	_switch_to_node(pong)


func _new_pong() -> PongScreen:
	var pong: PongScreen = PONG_SCENE.instantiate() as PongScreen
	pong.menu_requested.connect(show_menu)
	pong.play_again_requested.connect(_replay_pong.bind(pong))
	pong.network_requested.connect(_open_pong_lobby.bind(pong))
	return pong


func _open_pong_lobby(seats: int, pong: PongScreen) -> void:
	var lobby: PongLobby = PONG_LOBBY_SCENE.instantiate() as PongLobby
	lobby.back_requested.connect(lobby.queue_free)
	pong.cover_setup(lobby)
	lobby.choose_seats(seats)


func _on_autopilot_finished(_reason: String) -> void:
	CleanExit.quit(0)


func _on_quit_requested() -> void:
	CleanExit.quit(0)
