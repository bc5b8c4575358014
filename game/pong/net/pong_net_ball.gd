class_name PongNetBall
extends RefCounted
## A follower's ball in the local servo, as the network moves it. The master's states go
## into [member buffer] (by sequence, jitter-buffered); each one it plays is carried to now
## ([method PongNetSmoother.extrapolate]) and handed to the servo as a correction
## ([method PongServo.correct_ball]), which the servo blends in at 1 kHz without a jump
## while the ball flies on. A serve is put at once ([method put]). Our own paddle's touch
## is what the hand felt: a state the master sent before it cannot know of it and does not
## correct the ball (it would undo the touch under the hand).

## How far a state may lie from where the previous one's flight leads (the predictor models
## neither the air's drag nor the court's friction: a few centimetres over a gap) before it
## counts as news (a strike): position, metres, and velocity, m/s.
const AGREE_M: float = 0.1
const AGREE_M_PER_S: float = 1.0

var smoother: PongNetSmoother = PongNetSmoother.new()
## The master's states, in order.
var buffer: PongNetBallBuffer = PongNetBallBuffer.new()
## The servo is stepped by the game (commands land exactly at the next step); else its
## thread runs and a command lands about a tick later.
var stepped: bool = false
## The court the ball stays in: an extrapolation can end past a wall or under the floor,
## where the servo refuses the ball.
var court: PongCourt = null
## States played that did not correct the ball: sent before the master could know of our
## paddle's touch.
var ignored: int = 0

var _commanded: Array[Vector3] = []
var _commanded_time: float = 0.0
# Until when (this machine's clock, s) a state the master sent may not know of the last touch
# of a paddle this peer drives.
var _touch_unknown_until: float = -INF


## Our ball now, [position, velocity, spin]: the last [method put] while the servo has not
## taken it yet, else the servo's state.
func local() -> Array[Vector3]:
	var state: PongState = PongServo.shared().get_state()
	if not _commanded.is_empty() and state.time_s < _commanded_time + PongServo.COMMAND_LANDS_S:
		return _commanded
	_commanded = []
	return [state.ball_position, state.ball_velocity, state.ball_spin]


## Puts the ball there at once (a serve).
func put(position: Vector3, velocity: Vector3, spin: Vector3) -> void:
	var inside: Vector3 = _inside(position)
	_commanded_time = PongServo.shared().get_state().time_s
	_commanded = [inside, velocity, spin]
	PongServo.shared().set_ball(inside, velocity, spin)


## The master's ball, carried to now, is here: the servo blends ours onto it. The size of
## the correction is recorded.
func correct(position: Vector3, velocity: Vector3, spin: Vector3) -> void:
	var inside: Vector3 = _inside(position)
	smoother.record(local()[0], inside)
	_commanded = []
	PongServo.shared().correct_ball(inside, velocity, spin)


## A transfer carried the ball's state, [param age_s] old, to now: [param ball]. A serve
## puts it; any other transfer corrects ours, unless that state was sent before the master
## could know of our paddle's last touch (our ball then knows more than the state does).
func transfer(serve: bool, ball: Array[Vector3], age_s: float, now_s: float) -> void:
	if serve:
		put(ball[0], ball[1], ball[2])
	elif now_s - age_s > _touch_unknown_until:
		correct(ball[0], ball[1], ball[2])
	else:
		ignored += 1


## The stream's message of the ball in [param snapshot] (the corrected one: a correction
## may still be gliding in), the [param seq]th of [param epoch], sent over a leg of
## [param leg_ms] up.
static func state_of(snapshot: PongState, epoch: int, seq: int, leg_ms: int) -> PongNetBallMessage:
	var state: PongNetBallMessage = PongNetBallMessage.new()
	state.epoch = epoch
	state.seq = seq
	state.time_s = snapshot.time_s
	state.position = snapshot.ball_position + snapshot.ball_correction
	state.velocity = snapshot.ball_velocity
	state.spin = snapshot.ball_spin
	state.leg_ms = leg_ms
	return state


## This machine's clock, s (the one [PongNetLatency] ages messages by).
static func clock_s() -> float:
	return Time.get_ticks_usec() / 1e6


## A paddle this peer drives touched the ball at [param now_s] ([method clock_s]). Not a
## remote paddle's touch here: its pose arrives a path late, and trusting it as a predicted
## hit made the divergence worse (issue 24's path: docs/pong-networking.md).
## [param reach_s]: how long after it a state the master sends may still not know of it (our
## pose's way to the master, and the jitter). The master's ball hits our paddle only when our
## pose reaches it: a hand-off state sent in between, carried to now, put a ball our player
## had just returned back under the paddle, and the new master claimed its bounce.
func touched(now_s: float, reach_s: float = 0.0) -> void:
	_touch_unknown_until = now_s + maxf(reach_s, 0.0)


## Takes a state of the current master into the buffer; what became of it.
func take(state: PongNetBallBuffer.State) -> PongNetBallBuffer.Taken:
	return buffer.push(state)


## Plays what the buffer has due at [param now_s] and corrects the ball toward the newest
## state played, carried to now by [param predictor] under gravity [param g]. True when a
## state was played.
func follow(now_s: float, predictor: PongPredictor, g: float) -> bool:
	var agrees: Callable = func(from: PongNetBallBuffer.State, to: PongNetBallBuffer.State) -> bool:
		var flown: Array[Vector3] = PongNetSmoother.extrapolate(
			predictor, from.position, from.velocity, g, to.sent_at - from.sent_at
		)
		return (
			flown[0].distance_to(to.position) <= AGREE_M
			and flown[1].distance_to(to.velocity) <= AGREE_M_PER_S
		)
	if not buffer.advance(now_s, agrees):
		return false
	var state: PongNetBallBuffer.State = buffer.played
	var age: float = state.age_at(now_s)
	if now_s - age <= _touch_unknown_until:
		ignored += 1
		return true
	# A threaded servo takes the command a tick later.
	var lead: float = 0.0 if stepped else PongServo.TICK_S
	var target: Array[Vector3] = PongNetSmoother.extrapolate(
		predictor, state.position, state.velocity, g, age + lead
	)
	correct(target[0], target[1], state.spin)
	return true


## A new stream (a transfer): the buffered states of the old one are dropped.
func restart() -> void:
	buffer.restart()


## The buffer's counts and the ignored states, for the report.
func to_dict() -> Dictionary:
	var counts: Dictionary = buffer.to_dict()
	counts["ignored_after_touch"] = ignored
	return counts


func _inside(position: Vector3) -> Vector3:
	return position if court == null else court.clamp_inside(position, court.ball_radius)
