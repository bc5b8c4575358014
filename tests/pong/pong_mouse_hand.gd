extends RefCounted
## The clumsy first-time player (pong_clumsy_player.gd, its limits) at the game's own
## controls, as a person meets a match against the computer: the match's human player keeps
## its paddle on the device (the simulated one), and this moves it the way a person would,
## with mouse motion pushed into the viewport (a quarter of the window's height from its
## centre is the workspace's edge) and the walking keys pressed and released. The clumsy
## player decides where its avatar and paddle go; the keys and the mouse follow.

const PongClumsyPlayer := preload("res://tests/pong/pong_clumsy_player.gd")
## The walking keys are pressed while the avatar is this far behind the clumsy player's.
const WALK_SLACK_M: float = 0.05

var _match: PongMatch = null
var _brain: PongClumsyPlayer = null
var _pressed: Dictionary[StringName, bool] = {}


## Plays player 0 of [param match_node] (started, in the tree), its randomness from
## [param seed_value].
func _init(match_node: PongMatch, seed_value: int) -> void:
	_match = match_node
	_brain = PongClumsyPlayer.new(0, match_node.court, match_node.reach, seed_value)
	_brain.intent.avatar = match_node.avatar_of(0)


## One look at the match and the hand's move, after each of its updates of [param dt].
func act(dt: float) -> void:
	var brain: PongIntent = _brain.update(_match.now, dt, _match.snapshot, _match.avatar_of(1))
	var avatar: Vector3 = _match.avatar_of(0)
	var turn: Basis = PongCourt.side_rotation(0)
	var lag: Vector3 = turn.inverse() * (brain.avatar - avatar)
	_hold(&"move_left", lag.x < -WALK_SLACK_M)
	_hold(&"move_right", lag.x > WALK_SLACK_M)
	var hand: Vector3 = turn.inverse() * (brain.avatar + brain.paddle_offset - avatar)
	_push_mouse(Vector2(hand.x, -hand.y) / _match.reach)


# The mouse to [param planar] (screen directions, fractions of the workspace's radius).
func _push_mouse(planar: Vector2) -> void:
	var viewport: Viewport = _match.get_viewport()
	var size: Vector2 = viewport.get_visible_rect().size
	var motion: InputEventMouseMotion = InputEventMouseMotion.new()
	motion.position = size * 0.5 + planar.limit_length(1.0) * size.y * 0.25
	motion.global_position = motion.position
	viewport.push_input(motion, true)


## Lets go of every key it holds and puts the mouse back in the middle, where the door's
## simulated hand rests after the match (it follows the mouse once the mouse has moved).
func release() -> void:
	for action: StringName in _pressed:
		Input.action_release(action)
	_pressed.clear()
	_push_mouse(Vector2.ZERO)


func _hold(action: StringName, down: bool) -> void:
	if down and not _pressed.has(action):
		Input.action_press(action)
		_pressed[action] = true
	elif not down and _pressed.has(action):
		Input.action_release(action)
		_pressed.erase(action)
