class_name Main
extends Node
## Entry scene: the main menu and the screens it leads to (Play, the 3D room, the drive,
## Haptic Battle Pong, Maze study, Settings).
##
## After [code]--[/code] on the command line: [code]--system-check[/code] prints
## [method system_line] (what this installation found: the extension, the devices), shows the
## main menu for [constant SYSTEM_CHECK_FRAMES] frames and quits with exit code 0, for a
## player's report and the export's own test; [PongNetCli]'s options start networked Pong or
## its dedicated server.

const MENU_SCENE: PackedScene = preload("res://game/ui/main_menu.tscn")
const SETTINGS_SCENE: PackedScene = preload("res://game/common/ui/settings_screen.tscn")
## The maze user study.
const STUDY_SCENE: PackedScene = preload("res://game/study/session/study.tscn")
## One run of a level.
const GAME_SCENE: PackedScene = preload("res://game/main/game.tscn")
## The 3D level.
const ROOM_3D_SCENE: PackedScene = preload("res://game/level3d/room_3d.tscn")
## The drive (the vehicle renderer's scene).
const DRIVE_SCENE: PackedScene = preload("res://game/level3d/drive/drive.tscn")
## Haptic Battle Pong.
const PONG_SCENE: PackedScene = preload("res://game/pong/ui/pong.tscn")
## Networked Pong's lobby, over the Pong setup.
const PONG_LOBBY_SCENE: PackedScene = preload("res://game/pong/net/ui/pong_lobby.tscn")
## Frames the system check shows the main menu for before it quits.
const SYSTEM_CHECK_FRAMES: int = 60

## Whether [method _ready] reads the command line (tests turn it off, then drive the
## screens themselves).
@export var read_command_line: bool = true

var _screen: Node = null

@onready var _background: MenuBackground = $Background


func _ready() -> void:
	show_title.call_deferred()
	if not read_command_line:
		show_menu()
		return
	var args: PackedStringArray = OS.get_cmdline_user_args()
	if PongNetCli.wants(args):
		_background.visible = DisplayServer.get_name() != "headless"
		add_child(PongNetCli.new())
		return
	show_menu()
	if args.has("--system-check"):
		_system_check()


## One line on what this installation found: the haptics extension's and the engine's
## versions, how many devices are present, and the chosen device's state.
static func system_line() -> String:
	return (
		"%s; %d device(s) found; %s"
		% [
			Haptics.get_version(),
			Haptics.device.list_present().size(),
			MainMenu.device_status_text(),
		]
	)


## Titles the window with the game's name alone. In a debug build (the shipped game is one)
## the root [Window] adds " (DEBUG)" to any title it is given, so the name goes to the
## display server directly.
func show_title() -> void:
	if DisplayServer.get_name() == "headless":
		return
	var window: Window = get_window()
	var name_of_game: String = ProjectSettings.get_setting("application/config/name")
	DisplayServer.window_set_title(name_of_game, window.get_window_id())


## The screen showing now (a [MainMenu], [SettingsScreen], [StudyRunner] or [Game]).
func get_screen() -> Node:
	return _screen


func show_menu() -> void:
	var menu: MainMenu = _switch_to(MENU_SCENE) as MainMenu
	menu.play_requested.connect(start_game)
	menu.room_3d_requested.connect(start_room_3d)
	menu.drive_requested.connect(start_drive)
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


## Starts a run of the level, steered by [param pilot] instead of the person when given (a
## test driver's; see [member Game.pilot]).
func start_game(pilot: GamePilot = null) -> void:
	var game: Game = GAME_SCENE.instantiate() as Game
	game.pilot = pilot
	game.menu_requested.connect(show_menu)
	game.restart_requested.connect(start_game.bind(pilot))
	_switch_to_node(game)


## Starts a run of the 3D room, steered by [param pilot] instead of the person when given.
func start_room_3d(pilot: Room3DPilot = null) -> void:
	var room: Room3D = ROOM_3D_SCENE.instantiate() as Room3D
	room.pilot = pilot
	room.menu_requested.connect(show_menu)
	room.restart_requested.connect(start_room_3d.bind(pilot))
	_switch_to_node(room)


## Starts the drive; Esc returns to the title screen.
func start_drive() -> void:
	var drive: DriveScene = DRIVE_SCENE.instantiate() as DriveScene
	drive.menu_requested.connect(show_menu)
	_switch_to_node(drive)


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
	_background.visible = not (node is Game or node is PongScreen or node is Node3D)
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


# The menu shows for SYSTEM_CHECK_FRAMES frames, then the game quits as a player's Quit does.
func _system_check() -> void:
	print("System check: " + system_line())
	for _frame: int in SYSTEM_CHECK_FRAMES:
		await get_tree().process_frame
	if _screen is MainMenu:
		print("System check: the main menu showed for %d frames" % SYSTEM_CHECK_FRAMES)
		CleanExit.quit(0)
	else:
		push_error("System check: the main menu is not showing")
		CleanExit.quit(1)


func _on_quit_requested() -> void:
	CleanExit.quit(0)
