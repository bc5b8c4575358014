extends Node
## Entry scene: loads the level and, on a machine without a display (or with
## [code]-- --autopilot[/code]), drives the player with an autopilot for a bounded time,
## printing one status line per second, then quits with exit code 0.

## Level to load.
@export var level_scene: PackedScene = preload("res://scenes/levels/test_room.tscn")
## How long the autopilot runs before quitting, in seconds (0: forever).
@export var autopilot_seconds: float = 5.0

var _level: Node = null
var _player: Player = null
var _autopilot: bool = false
var _elapsed: float = 0.0
var _next_report: float = 1.0


func _ready() -> void:
	_level = level_scene.instantiate()
	add_child(_level)
	_player = _level.get_node(^"Player") as Player
	var args: PackedStringArray = OS.get_cmdline_user_args()
	_autopilot = DisplayServer.get_name() == "headless" or args.has("--autopilot")
	for arg: String in args:
		if arg.begins_with("--autopilot-seconds="):
			autopilot_seconds = arg.get_slice("=", 1).to_float()
	if _autopilot:
		_player.use_keyboard = false
		print(
			(
				"Autopilot on (no display): %s; %d device(s) found"
				% [Haptics.get_version(), Haptics.list_devices().size()]
			)
		)


func _physics_process(delta: float) -> void:
	if not _autopilot:
		return
	_elapsed += delta
	# Sweep the input around a circle so the body meets every wall and the slope.
	var angle: float = _elapsed * 0.9
	_player.input_vector = Vector2(cos(angle), sin(angle * 1.3))
	if _elapsed >= _next_report:
		_next_report += 1.0
		print(_status_line())
	if autopilot_seconds > 0.0 and _elapsed >= autopilot_seconds:
		get_tree().quit(0)


func _status_line() -> String:
	var iv: Vector2 = _player.input_vector
	return (
		"t=%4.1fs input=(%+.2f, %+.2f) pos=(%4.0f, %4.0f) contacts=%d"
		% [
			_elapsed,
			iv.x,
			iv.y,
			_player.position.x,
			_player.position.y,
			_player.get_slide_collision_count()
		]
	)
