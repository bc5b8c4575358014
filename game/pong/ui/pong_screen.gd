class_name PongScreen
extends Node
## The Haptic Battle Pong screen: the setup (who plays, beginner mode), then the match
## ([PongMatch]) drawn by [PongView] with the [PongHud], the pause menu (Esc) and the
## winner screen. Without the extension's Pong renderer it says why and offers the way
## back: the ball lives in the servo, and there is no other ball.
##
## Runs on its own (F6): it starts on the setup; Menu then quits and Play again reloads.
## [member skip_setup] starts the match straight away (Play again, tests and the headless
## demo of [code]tests/drivers/[/code], which watch [member match_node] themselves).

## Back to the main menu (pause menu's Quit to menu, the winner screen's Menu, setup's Back).
signal menu_requested
## Play again with the same settings.
signal play_again_requested
## The setup's Network game: whoever listens opens the lobby (a level above Pong's) over
## this screen with [method cover_setup], [param seats] (the setup's court) its first
## choice of seats. With nobody listening (the scene on its own) the button is hidden.
signal network_requested(seats: int)

## Shown instead of a game when there is no Pong renderer.
const OFFLINE_TEXT: String = (
	"Haptic Battle Pong needs the haptics extension: the ball is simulated in its 1 kHz "
	+ "servo. Build it with 'make build' (see README)."
)
const OLD_EXTENSION_TEXT: String = (
	"This build of the haptics extension has no Pong renderer: " + "rebuild it with 'make build'."
)

## Start the match without the setup, with the settings below.
@export var skip_setup: bool = false
@export var mode: PongMatch.Mode = PongMatch.Mode.VS_COMPUTER
@export var beginner: bool = false
## How hard the computer plays against people.
@export var difficulty: PongAiLevel.Level = PongAiLevel.Level.EASY
@export var start_health: int = PongRules.DEFAULT_START_HEALTH
## 2, or 4 on a square court.
@export_enum("2:2", "4:4") var players: int = 2
## Run the servo by hand, faster than real time (computer vs computer).
@export var stepped: bool = false
## The seat whose side the camera shows (-1: the device player's, else player 0's). A
## network match sets its own player's seat.
var viewer_seat: int = -1
## Names by seat that replace the ones the controllers give (a network match: the lobby's).
var seat_names: Dictionary[int, String] = {}
## Whether anyone sees this screen: a headless peer's view and HUD are not refreshed (at its
## 1000 frames a second they were a large share of its CPU, for nobody).
var drawn: bool = true

var _running: bool = false
var _frames_before_court: int = 2

## The match's sounds.
@onready var sounds: PongSounds = $Sounds
@onready var world: PongView = $World
@onready var match_node: PongMatch = $Match
@onready var hud: PongHud = $Hud
@onready var pause_menu: PauseMenu = $PauseMenu
@onready var winner_screen: PongWinnerScreen = $WinnerScreen
@onready var setup: PongSetup = $Setup


func _ready() -> void:
	hud.visible = false
	pause_menu.enabled = false
	pause_menu.quit_requested.connect(_leave)
	winner_screen.play_again_requested.connect(_play_again)
	winner_screen.menu_requested.connect(_leave)
	setup.start_requested.connect(_on_setup_start)
	setup.back_requested.connect(_leave)
	setup.network_requested.connect(func() -> void: network_requested.emit(setup.get_players()))
	setup.network_button.visible = not network_requested.get_connections().is_empty()
	if not PongServo.shared().is_available():
		setup.show_offline(OFFLINE_TEXT if not Haptics.is_available() else OLD_EXTENSION_TEXT)
		return
	if skip_setup:
		start_match(mode, beginner)
		return
	setup.court_changed.connect(_preview)
	# The court's first frame takes seconds to draw (its shaders compile): the setup shows
	# first, saying so, and offers its buttons once the preview's frames are drawn.
	setup.set_preparing(true)
	get_tree().process_frame.connect(_prepare_court)


func _process(delta: float) -> void:
	if not _running or not drawn:
		return
	world.render(match_node)
	if hud.visible:
		hud.refresh(match_node, delta)


## Starts a match in [param p_mode]; false when the servo has no Pong renderer.
func start_match(p_mode: PongMatch.Mode, p_beginner: bool) -> bool:
	mode = p_mode
	beginner = p_beginner
	match_node.mode = mode
	match_node.beginner = beginner
	match_node.difficulty = difficulty
	match_node.start_health = start_health
	match_node.players = players
	match_node.stepped = stepped
	if not match_node.start():
		setup.show_offline(OLD_EXTENSION_TEXT)
		return false
	setup.visible = false
	var viewer: int = viewer_seat if viewer_seat >= 0 else maxi(match_node.local_player, 0)
	world.build(match_node.court, match_node.reach, beginner, viewer)
	var titles: Array[String] = []
	for player: int in match_node.court.players:
		titles.append(player_name(player))
	hud.setup(
		titles,
		PongView.PLAYER_COLORS,
		start_health,
		ForcePlot.full_scale(Haptics.device.get_max_force()),
		mode == PongMatch.Mode.TWO_PLAYERS
	)
	hud.visible = true
	pause_menu.enabled = true
	sounds.listen(match_node)
	match_node.served.connect(_on_served)
	match_node.mine_placed.connect(world.add_mine)
	match_node.mines.restored.connect(world.add_mine)
	match_node.mine_exploded.connect(_on_mine_exploded)
	match_node.bullet_hit.connect(_on_bullet_hit)
	match_node.match_over.connect(_on_match_over)
	match_node.player_out.connect(_on_player_out)
	if beginner:
		hud.flash("Beginner mode: send the ball into the target behind your opponent")
	_running = true
	return true


func _prepare_court() -> void:
	# The second frame after the screen came: a click makes it before the first frame's
	# processing, whose drawing would then carry the court with the setup's first look.
	_frames_before_court -= 1
	if _frames_before_court > 0:
		return
	get_tree().process_frame.disconnect(_prepare_court)
	world.previewed.connect(_on_court_prepared, CONNECT_ONE_SHOT)
	_preview_chosen()


func _on_court_prepared() -> void:
	# Drawn at the end of this frame; the next one starts after it.
	get_tree().process_frame.connect(setup.set_preparing.bind(false), CONNECT_ONE_SHOT)


func _preview_chosen() -> void:
	_preview(setup.get_players(), setup.beginner_check.button_pressed)


## The court of [param p_players] behind the setup, until a match starts.
func _preview(p_players: int, p_beginner: bool) -> void:
	if _running or not is_inside_tree():
		return
	var settings: PongSettings = PongServo.shared().get_settings()
	settings.players = p_players
	var court: PongCourt = PongCourt.from_settings(settings)
	world.preview(court, Haptics.device.get_workspace_radius() * court.workspace_scale, p_beginner)


func _on_setup_start(p_mode: PongMatch.Mode, p_beginner: bool) -> void:
	players = setup.get_players()
	difficulty = setup.get_difficulty()
	start_match(p_mode, p_beginner)


## Whether a match runs (false on the setup or without the renderer).
func is_running() -> bool:
	return _running


## How [param player] is named on the HUD and the winner screen.
func player_name(player: int) -> String:
	if seat_names.has(player):
		return seat_names[player]
	var controller: PongController = match_node.controllers[player]
	if controller is PongAi:
		return "Computer" if mode != PongMatch.Mode.DEMO else "Computer %d" % (player + 1)
	if player == match_node.local_player:
		return "You · device"
	return "You · mouse" if player == 0 else "Player 2 · keyboard"


## Names [param player] [param title] from now on (a network player left: the computer
## plays the seat).
func rename_player(player: int, title: String) -> void:
	seat_names[player] = title
	if _running:
		hud.get_panel(player).set_player(title, PongView.PLAYER_COLORS[player], start_health)


## Shows [param screen] (the network lobby) instead of the setup, which comes back when
## [param screen] leaves.
func cover_setup(screen: Node) -> void:
	setup.visible = false
	# The court behind the setup goes with it: a match the lobby starts draws its own.
	world.clear()
	screen.tree_exiting.connect(_uncover_setup)
	add_child(screen)


func _uncover_setup() -> void:
	setup.visible = true
	_preview_chosen()


func _is_own_scene() -> bool:
	return get_tree().current_scene == self


func _leave() -> void:
	if _is_own_scene():
		CleanExit.quit(0)
	else:
		menu_requested.emit()


func _play_again() -> void:
	if _is_own_scene():
		get_tree().reload_current_scene()
	else:
		play_again_requested.emit()


func _on_served(receiver: int) -> void:
	hud.flash("Serve to %s" % player_name(receiver))


func _on_mine_exploded(mine: PongMines.Mine, victim: int) -> void:
	world.explode_mine(mine)
	hud.flash("%s stepped on a %s mine!" % [player_name(victim), PongMines.kind_name(mine.kind)])


func _on_bullet_hit(hit: Dictionary) -> void:
	var victim: int = hit["victim"]
	hud.flash("%s is hit!" % player_name(victim))


func _on_player_out(player: int) -> void:
	hud.flash("%s is out!" % player_name(player))


func _on_match_over(winner: int) -> void:
	pause_menu.enabled = false
	# The winner screen pauses the tree at once: the HUD shows the last hurt under it.
	hud.refresh(match_node, 0.0)
	var health: Array[int] = []
	for player: int in match_node.court.players:
		health.append(match_node.rules.get_health(player))
	winner_screen.show_winner(player_name(winner), health)
