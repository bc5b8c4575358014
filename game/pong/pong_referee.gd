class_name PongReferee
extends RefCounted
## When and how the ball is served. Serves are made from above the centre line, toward the
## receiver, who must return the ball before it bounces in their territory:
## [br]- at the start of the match ([constant FIRST_SERVE_DELAY_S] after it);
## [br]- after a stall: the ball slower than [constant STALL_SPEED_M_PER_S] for more than
## [constant STALL_SECONDS] (it rolls or rests and nobody can reach it);
## [br]- in beginner mode, [constant GOAL_SERVE_DELAY_S] after a goal.
## Receivers take turns, player 0 first (then 1, 2, 3 with four players; the match skips
## players who are out). A serve reaches the receiver's workspace centre
## after [constant SERVE_FLIGHT_S] (under gravity: a lob that comes down into the
## workspace; in beginner mode: straight, in the ball's plane, at
## [constant BEGINNER_SERVE_SPEED_M_PER_S]).


## A ball to put in play.
class Serve:
	extends RefCounted
	var position: Vector3 = Vector3.ZERO
	var velocity: Vector3 = Vector3.ZERO


const FIRST_SERVE_DELAY_S: float = 1.0
const STALL_SPEED_M_PER_S: float = 0.3
const STALL_SECONDS: float = 2.0
const GOAL_SERVE_DELAY_S: float = 0.8
const SERVE_HEIGHT_M: float = 1.2
const SERVE_FLIGHT_S: float = 1.1
const BEGINNER_SERVE_SPEED_M_PER_S: float = 2.5

## The player the next serve goes to.
var receiver: int = 0
## How many players take turns receiving.
var players: int = 2
## Serves made so far.
var serves: int = 0

var _countdown: float = FIRST_SERVE_DELAY_S
var _still_for: float = 0.0


## Advances the referee's clock by [param dt] with the ball's current [param velocity];
## true when it is time to serve (then [method make_serve] gives the ball).
func update(dt: float, velocity: Vector3) -> bool:
	if _countdown >= 0.0:
		_countdown -= dt
		if _countdown < 0.0:
			return true
		return false
	_still_for = _still_for + dt if velocity.length() < STALL_SPEED_M_PER_S else 0.0
	return _still_for > STALL_SECONDS


## A serve will follow in [param delay_s] seconds (after a goal).
func serve_after(delay_s: float) -> void:
	_countdown = delay_s


## Seconds until a scheduled serve (negative when none is scheduled).
func time_to_serve() -> float:
	return _countdown


## The next serve (world) toward [member receiver], whose workspace centre is
## [param target]; advances the receiver.
func make_serve(court: PongCourt, target: Vector3, beginner: bool) -> Serve:
	var serve: Serve = Serve.new()
	serve.position = Vector3(0.0, SERVE_HEIGHT_M, 0.0)
	if beginner:
		serve.position.y = court.beginner_height
		var aim: Vector3 = Vector3(target.x, serve.position.y, target.z)
		serve.velocity = (aim - serve.position).normalized() * BEGINNER_SERVE_SPEED_M_PER_S
	else:
		serve.velocity = launch_velocity(serve.position, target, court.gravity, SERVE_FLIGHT_S)
	receiver = (receiver + 1) % players
	serves += 1
	_countdown = -1.0
	_still_for = 0.0
	return serve


## The velocity that takes a ball from [param from] to [param to] in [param flight_s]
## seconds under gravity [param g] (no drag, no bounce).
static func launch_velocity(from: Vector3, to: Vector3, g: float, flight_s: float) -> Vector3:
	return (to - from) / flight_s + Vector3(0.0, 0.5 * g * flight_s, 0.0)
