class_name Game
extends Node
## One run of a level: the level, the HUD, the pause menu and the goal screen.
##
## The player steers with the haptic device or the keyboard as [code]Haptics.control_mode[/code]
## says (the level's [HapticProbe] feeds the device's input vector; the [code]Haptics[/code]
## autoload moves the simulated hand with the mouse), or a [member pilot] steers instead.

## The player chose Quit to menu (pause menu) or Menu (goal screen).
signal menu_requested
## The player chose Play again on the goal screen.
signal restart_requested

## The level the game plays.
const LEVEL_1_PATH: String = "res://game/levels/level_1.tscn"

## Level to play; level 1 ([constant LEVEL_1_PATH]) when null.
@export var level_scene: PackedScene = null

## The level being played.
var level: Level = null
## The level's avatar.
var player: Player = null
## Game time since the start, in seconds (stops at the goal; not counted while paused).
var elapsed: float = 0.0
## Items collected so far.
var collected: int = 0
## Items in the level, or -1 while unknown.
var total_items: int = -1
## Whether the goal was reached.
var finished: bool = false
## Who steers in place of the person ([GamePilot]; null: the person, with the keys, the
## gamepad or the device). Set it before the game enters the tree.
var pilot: GamePilot = null

var _ticks: int = 0
var _stopped: bool = false
var _control_text: String = ""

@onready var hud: Hud = $Hud
@onready var pause_menu: PauseMenu = $PauseMenu
@onready var goal_screen: GoalScreen = $GoalScreen


func _ready() -> void:
	var scene: PackedScene = level_scene
	if scene == null:
		scene = load(LEVEL_1_PATH) as PackedScene
	if scene == null:
		push_error("The level is missing: %s" % LEVEL_1_PATH)
		return
	level = scene.instantiate() as Level
	if level == null:
		push_error("The level scene's root is not a Level: %s" % scene.resource_path)
		return
	add_child(level)
	move_child(level, 0)
	player = level.player
	level.goal_reached.connect(_on_goal_reached)
	level.item_collected.connect(_on_item_collected)
	total_items = level.get_item_total()
	hud.set_player(player)
	hud.set_run_info(0.0, 0, total_items)
	hud.view = Hud.View.LAB if Settings.lab_view else Hud.View.COMPACT
	hud.view_changed.connect(_on_hud_view_changed)
	pause_menu.quit_requested.connect(menu_requested.emit)
	goal_screen.play_again_requested.connect(restart_requested.emit)
	goal_screen.menu_requested.connect(menu_requested.emit)
	if pilot != null:
		player.use_keyboard = false
		Haptics.hand_follows_input = false
		pilot.start(self)


func _exit_tree() -> void:
	if pilot != null:
		Haptics.device.set_hand_target(Vector2.ZERO)
		Haptics.hand_follows_input = true


func _physics_process(delta: float) -> void:
	if player == null or finished or _stopped:
		return
	_ticks += 1
	elapsed = _ticks * delta
	_steer(delta)
	hud.set_run_info(elapsed, collected, total_items)


## Whether the player steers with the haptic device (rather than keys or a pilot).
func uses_device_control() -> bool:
	return pilot == null and Haptics.control_mode == Haptics.CONTROL_DEVICE


func _steer(delta: float) -> void:
	var text: String = "keyboard / gamepad"
	if pilot != null:
		player.use_keyboard = false
		if not pilot.steer(self, delta):
			_stopped = true
			player.input_vector = Vector2.ZERO
		# The simulated hand follows, so the device agrees with what the pilot does.
		Haptics.device.set_hand_target(player.input_vector)
		text = pilot.get_label()
	elif uses_device_control():
		text = "haptic device" if Haptics.servo.is_running() else "device (not running)"
	if text != _control_text:
		_control_text = text
		hud.set_control_text(text)


func _on_item_collected(p_collected: int, total: int) -> void:
	collected = p_collected
	total_items = total
	hud.set_run_info(elapsed, collected, total_items)


func _on_goal_reached() -> void:
	if finished:
		return
	finished = true
	pause_menu.enabled = false
	player.input_vector = Vector2.ZERO
	if pilot == null:
		goal_screen.show_result(elapsed, collected, total_items)


# The H key's choice is the player's setting from then on.
func _on_hud_view_changed(view: Hud.View) -> void:
	Settings.lab_view = view == Hud.View.LAB
	Settings.save_settings()
