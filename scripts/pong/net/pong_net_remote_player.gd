class_name PongNetRemotePlayer
extends PongController
## A player on another machine: its avatar and paddle come in the pose stream and reach
## the local servo as a kinematic paddle. The paddle is carried forward by its velocity
## over the pose's age (at most [constant MAX_EXTRAPOLATION_S]); the servo itself carries
## it on for 50 ms after each input.

## Longest extrapolation of a remote paddle, seconds (a stalled stream holds the paddle).
const MAX_EXTRAPOLATION_S: float = 0.15

## Poses taken.
var poses: int = 0

var _received_at: float = -1.0
var _age_s: float = 0.0


func _init(p_player: int) -> void:
	player = p_player
	kinematic = true


## A pose of this player: [param age_s] seconds old when it arrived at [param now].
func set_pose(
	now: float,
	age_s: float,
	avatar: Vector3,
	offset: Vector3,
	velocity: Vector3,
	normal: Vector3,
	flags: int
) -> void:
	intent.avatar = avatar
	intent.paddle_offset = offset
	intent.paddle_velocity = velocity
	intent.normal = normal.normalized()
	intent.spin = flags & 1 != 0
	intent.gun = flags & 2 != 0
	_received_at = now
	_age_s = age_s
	poses += 1


## The pose flags of [param p_intent] (spin, gun).
static func flags_of(p_intent: PongIntent) -> int:
	return (1 if p_intent.spin else 0) | (2 if p_intent.gun else 0)


func update(
	now: float, _dt: float, _snapshot: PongSnapshot, _opponent_avatar: Vector3
) -> PongIntent:
	if _received_at < 0.0:
		return intent
	var ahead: float = minf(_age_s + now - _received_at, MAX_EXTRAPOLATION_S)
	var out: PongIntent = PongIntent.new()
	out.avatar = intent.avatar
	out.paddle_offset = intent.paddle_offset + intent.paddle_velocity * ahead
	out.paddle_velocity = intent.paddle_velocity
	out.normal = intent.normal
	out.spin = intent.spin
	out.gun = intent.gun
	return out
