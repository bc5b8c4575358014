class_name PongNetRemotePlayer
extends PongController
## A player on another machine: its avatar and paddle come in the pose stream and reach
## the local servo as a kinematic paddle, with the pose's age ([member PongIntent.pose_age_s]:
## its age when it arrived plus the time since). The servo carries the paddle on by its
## velocity over that age (at most 150 ms: a stalled stream holds the paddle), and the
## remote-operation mine's target, this player's stylus, too (hand_effects.h); so the age is
## the servo's to use, once, and the pose is passed on as it came.

## Ages handed to the servo are capped here, seconds (the servo's own caps are lower; this
## only keeps a long stall within its input checks).
const MAX_AGE_S: float = 1.0

## Poses taken.
var poses: int = 0

var _received_at: float = -1.0
var _age_s: float = 0.0


func _init(p_player: int) -> void:
	player = p_player
	kinematic = true


## A [param pose] of this player: [param age_s] seconds old when it arrived at [param now].
func set_pose(now: float, age_s: float, pose: PongNetPoseMessage) -> void:
	intent.avatar = pose.avatar
	intent.paddle_offset = pose.offset
	intent.paddle_velocity = pose.velocity
	intent.normal = pose.normal.normalized()
	intent.spin = pose.spin
	intent.gun = pose.gun
	_received_at = now
	_age_s = age_s
	poses += 1


func update(now: float, _dt: float, _snapshot: PongState, _opponent_avatar: Vector3) -> PongIntent:
	# Its peer fires and places its mines (and says so): never here. The intent may be the
	# one of the computer player this seat had before.
	intent.fire = false
	intent.place_mine = false
	if _received_at >= 0.0:
		intent.pose_age_s = minf(_age_s + maxf(now - _received_at, 0.0), MAX_AGE_S)
	return intent
