class_name PongNetBall
extends RefCounted
## A follower's ball in the local servo, as the network moves it: each received target
## goes through [member smoother] (velocity and spin at once, the position blended), and
## every set_ball is remembered until the servo has taken it, because a command reaches
## the servo only at its next tick: a second correction in the same frame must start from
## the commanded ball, not from the servo's older state.

## Smallest pending correction worth a set_ball, metres.
const MIN_NUDGE_M: float = 0.0005

var smoother: PongNetSmoother = PongNetSmoother.new()
## The servo is stepped by the game (commands land exactly at the next step); else its
## thread runs and a command lands about a tick later.
var stepped: bool = false
## The court the ball stays in: a blend or an extrapolation can end past a wall or under the
## floor (a correction pointing down as the ball lands), where the servo refuses the ball.
var court: PongCourt = null

var _commanded: Array[Vector3] = []
var _commanded_time: float = 0.0


## Our ball now, [position, velocity, spin]: the last set_ball while the servo has not
## taken it yet, else the servo's state.
func local() -> Array[Vector3]:
	var state: HapticPongState = Haptics.pong.get_state()
	if not _commanded.is_empty() and state.time_s < _commanded_time + 1.5 * HapticsPong.TICK_S:
		return _commanded
	_commanded = []
	return [state.ball_position, state.ball_velocity, state.ball_spin]


## Puts the ball there (a serve, a new master's start).
func put(position: Vector3, velocity: Vector3, spin: Vector3) -> void:
	var inside: Vector3 = position
	if court != null:
		inside = court.clamp_inside(position, court.ball_radius)
	_commanded_time = Haptics.pong.get_state().time_s
	_commanded = [inside, velocity, spin]
	Haptics.pong.set_ball(inside, velocity, spin)


## The master's ball, carried to now, is here: take its velocity and spin, blend toward
## its position (or snap when far off).
func correct(position: Vector3, velocity: Vector3, spin: Vector3) -> void:
	var here: Vector3 = local()[0]
	if smoother.on_target(here, position):
		put(position, velocity, spin)
	else:
		put(here, velocity, spin)


## Applies the part of the pending correction due over [param dt] seconds.
func nudge(dt: float) -> void:
	var part: Vector3 = smoother.take(dt)
	if part.length() < MIN_NUDGE_M:
		return
	var ball: Array[Vector3] = local()
	var lead: float = 0.0 if stepped else HapticsPong.TICK_S
	put(ball[0] + ball[1] * lead + part, ball[1], ball[2])
