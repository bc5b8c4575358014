class_name Game
extends Node
## One run of a level: the level, the HUD, the pause menu and the goal screen.
##
## The player steers with the haptic device or the keyboard as [code]Haptics.control_mode[/code]
## says (the level's [HapticProbe] feeds the device's input vector; the [code]Haptics[/code]
## autoload moves the simulated hand with the mouse), or an [Autopilot] follows
## [method Level.get_autopilot_path], moving the simulated hand along. With the autopilot
## on, one status line is printed per second of game time and [signal autopilot_finished]
## is emitted at the goal or after [member autopilot_seconds].

## The player chose Quit to menu (pause menu) or Menu (goal screen).
signal menu_requested
## The player chose Play again on the goal screen.
signal restart_requested
## The autopilot run ended: [param reason] is [code]"goal"[/code] or [code]"time"[/code].
signal autopilot_finished(reason: String)

## The full level.
const LEVEL_1_PATH: String = "res://game/levels/level_1.tscn"
## The level used while the full one does not exist.
const FALLBACK_LEVEL_PATH: String = "res://game/levels/test_room.tscn"

## Level to play; [method default_level_path] when null.
@export var level_scene: PackedScene = null
## Drive the player with the autopilot.
@export var autopilot: bool = false
## Game seconds after which the autopilot run ends (0: only at the goal).
@export var autopilot_seconds: float = 5.0
## Print a status line per second while the autopilot drives.
@export var print_status: bool = true

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

var _pilot: Autopilot = null
var _ticks: int = 0
var _autopilot_done: bool = false
var _control_text: String = ""

@onready var hud: Hud = $Hud
@onready var pause_menu: PauseMenu = $PauseMenu
@onready var goal_screen: GoalScreen = $GoalScreen


func _ready() -> void:
	var scene: PackedScene = level_scene
	if scene == null:
		scene = load(default_level_path()) as PackedScene
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
	pause_menu.quit_requested.connect(menu_requested.emit)
	goal_screen.play_again_requested.connect(restart_requested.emit)
	goal_screen.menu_requested.connect(menu_requested.emit)
	if autopilot:
		_pilot = Autopilot.new(level.get_autopilot_path())
		player.use_keyboard = false
		Haptics.hand_follows_input = false


func _exit_tree() -> void:
	if _pilot != null:
		Haptics.device.set_hand_target(Vector2.ZERO)
		Haptics.hand_follows_input = true


func _physics_process(delta: float) -> void:
	if player == null or finished or _autopilot_done:
		return
	_ticks += 1
	elapsed = _ticks * delta
	_steer(delta)
	hud.set_run_info(elapsed, collected, total_items)
	if not autopilot:
		return
	if _ticks % Engine.physics_ticks_per_second == 0 and print_status:
		print(status_line())
	if autopilot_seconds > 0.0 and _ticks >= roundi(autopilot_seconds / delta):
		_finish_autopilot("time")


## The level played when none is given: level 1, or the test room until it exists.
static func default_level_path() -> String:
	if ResourceLoader.exists(LEVEL_1_PATH):
		return LEVEL_1_PATH
	return FALLBACK_LEVEL_PATH


## Whether the player steers with the haptic device (rather than keys or the autopilot).
func uses_device_control() -> bool:
	return _pilot == null and Haptics.control_mode == Haptics.CONTROL_DEVICE


## The autopilot's once-a-second line: time, servo rate, input, total force, contacts.
func status_line() -> String:
	var rate: float = Haptics.servo.get_rate_hz()
	var servo: String = "%d Hz" % roundi(rate) if rate > 0.0 else "off"
	var input: Vector2 = player.input_vector
	var force: Vector2 = Haptics.get_forces().total
	return (
		"t=%4.1fs servo=%s input=(%+.2f, %+.2f) force=(%+.2f, %+.2f) N |F|=%.2f N contacts=%d"
		% [
			elapsed,
			servo,
			_tidy(input.x),
			_tidy(input.y),
			_tidy(force.x),
			_tidy(force.y),
			force.length(),
			player.get_slide_collision_count(),
		]
	)


## The autopilot steering the player, or null.
func get_autopilot() -> Autopilot:
	return _pilot


func _steer(delta: float) -> void:
	var text: String = "keyboard / gamepad"
	if _pilot != null and _pilot.path.size() < 2:
		# No path (a bare test room): sweep round a circle to meet every wall.
		var angle: float = elapsed * 0.9
		player.input_vector = Vector2(cos(angle), sin(angle * 1.3)).limit_length(1.0)
	if _pilot != null:
		if _pilot.path.size() >= 2:
			_pilot.drive(player, delta)
		player.use_keyboard = false
		# The simulated hand follows, so the device agrees with what the autopilot does.
		Haptics.device.set_hand_target(player.input_vector)
		text = "autopilot"
	elif uses_device_control():
		text = "haptic device" if Haptics.servo.is_running() else "device (not running)"
	if text != _control_text:
		_control_text = text
		hud.set_control_text(text)


# Rounds what prints as ±0.00 to a plain zero, so the lines never show "-0.00".
static func _tidy(value: float) -> float:
	return 0.0 if absf(value) < 0.005 else value


func _finish_autopilot(reason: String) -> void:
	if _autopilot_done:
		return
	_autopilot_done = true
	player.input_vector = Vector2.ZERO
	autopilot_finished.emit(reason)


func _on_item_collected(p_collected: int, total: int) -> void:
	collected = p_collected
	total_items = total
	hud.set_run_info(elapsed, collected, total_items)


func _on_goal_reached() -> void:
	if finished:
		return
	finished = true
	pause_menu.enabled = false
	if autopilot:
		if print_status:
			print("goal reached at t=%.1fs" % elapsed)
		_finish_autopilot("goal")
	else:
		player.input_vector = Vector2.ZERO
		goal_screen.show_result(elapsed, collected, total_items)
