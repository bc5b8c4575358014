class_name LevelPilot
extends GamePilot
## The side-scroller's autopilot: steers a [Game]'s player along its level's
## [method Level.get_autopilot_path] with an [Autopilot] (round a circle, to meet every wall,
## where the level has no path), prints [method status_line] once per second of game time
## while [member print_status] is on, and says [signal finished] at the goal or after
## [member seconds].

## The run ended: [param reason] is [code]"goal"[/code] or [code]"time"[/code].
signal finished(reason: String)

## Game seconds after which the run ends (0: only at the goal).
var seconds: float = 5.0
## Print a status line per second of game time, and one at the goal.
var print_status: bool = true
## The waypoint follower (null until the run starts).
var autopilot: Autopilot = null

var _game: Game = null
var _ticks: int = 0
var _done: bool = false


func get_label() -> String:
	return "autopilot"


func start(game: Game) -> void:
	_game = game
	autopilot = Autopilot.new(game.level.get_autopilot_path())
	game.level.goal_reached.connect(_on_goal_reached)


func steer(game: Game, delta: float) -> bool:
	_ticks += 1
	var player: Player = game.player
	if autopilot.path.size() >= 2:
		autopilot.drive(player, delta)
	else:
		# No path (a bare room): sweep round a circle to meet every wall.
		var angle: float = game.elapsed * 0.9
		player.input_vector = Vector2(cos(angle), sin(angle * 1.3)).limit_length(1.0)
	if print_status and _ticks % Engine.physics_ticks_per_second == 0:
		print(status_line())
	if seconds > 0.0 and _ticks >= roundi(seconds / delta):
		_finish("time")
		return false
	return true


## The once-a-second line: time, servo rate, input, total force, contacts.
func status_line() -> String:
	var rate: float = Haptics.servo.get_rate_hz()
	var servo: String = "%d Hz" % roundi(rate) if rate > 0.0 else "off"
	var input: Vector2 = _game.player.input_vector
	var force: Vector2 = Haptics.get_forces().total
	return (
		"t=%4.1fs servo=%s input=(%+.2f, %+.2f) force=(%+.2f, %+.2f) N |F|=%.2f N contacts=%d"
		% [
			_game.elapsed,
			servo,
			_tidy(input.x),
			_tidy(input.y),
			_tidy(force.x),
			_tidy(force.y),
			force.length(),
			_game.player.get_slide_collision_count(),
		]
	)


# Rounds what prints as ±0.00 to a plain zero, so the lines never show "-0.00".
static func _tidy(value: float) -> float:
	return 0.0 if absf(value) < 0.005 else value


func _finish(reason: String) -> void:
	if _done:
		return
	_done = true
	finished.emit(reason)


func _on_goal_reached() -> void:
	if print_status:
		print("goal reached at t=%.1fs" % _game.elapsed)
	_finish("goal")
