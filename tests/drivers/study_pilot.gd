class_name StudyPilot
extends RefCounted
## The scripted participant's hand ([ScriptedParticipant]): steers the simulated device along
## a level's autopilot path, the way a person would hold the handle.
##
## Acceleration control: the hand is deflected by [method Autopilot.steer]'s input vector
## toward the next waypoint, so the avatar accelerates there through the real device, probe
## and physics. Position control: a target point travels along the path at [member speed]
## (waiting while the proxy lags behind it, as at a wall), and the hand is put where the
## maze map places that point; the proxy follows the device. Before a trial starts the hand
## goes to [method ConditionRig.start_hand]. With [member touch_walls] it first pushes into
## the walls around the start ([WallPushes]).

## Path in maze units, start to goal.
var path: PackedVector2Array = PackedVector2Array()
## Target speed along the path in position control, maze units per second.
var speed: float = 260.0
## Seconds to keep still at the start of each trial (lets tests act mid-trial).
var hold_s: float = 0.0
## Push into the walls around the start (and, in position control, through them) before
## heading for the goal: the participant who touches the walls.
var touch_walls: bool = false
## The wall pushes of [member touch_walls] (their progress, for tests).
var pushes: WallPushes = null

var _autopilot: Autopilot = null
var _carrot: Vector2 = Vector2.ZERO
var _segment: int = 0
var _held: float = 0.0


func _init(p_path: PackedVector2Array = PackedVector2Array(), p_speed: float = 260.0) -> void:
	path = p_path
	speed = p_speed
	_autopilot = Autopilot.new(p_path)
	pushes = WallPushes.new(p_speed)
	_carrot = p_path[0] if not p_path.is_empty() else Vector2.ZERO


## The hand target for this tick (normalised, game axes) while the trial runs.
func steer(rig: ConditionRig, delta: float) -> Vector2:
	if _held < hold_s:
		_held += delta
		return rig.start_hand()
	if touch_walls and not pushes.is_finished():
		return pushes.steer(rig, delta)
	if StudyFormat.is_position_control(rig.condition):
		return rig.map.hand_of(_advance(rig.avatar_position(), delta))
	var player: Player = rig.player
	return _autopilot.steer(
		player.global_position, player.velocity, player.max_speed, player.acceleration, delta
	)


func _advance(avatar: Vector2, delta: float) -> Vector2:
	if _carrot.distance_to(avatar) > 40.0:
		return _carrot
	var step: float = speed * delta
	while step > 0.0 and _segment < path.size() - 1:
		var target: Vector2 = path[_segment + 1]
		var left: float = _carrot.distance_to(target)
		if left <= step:
			_carrot = target
			_segment += 1
			step -= left
		else:
			_carrot = _carrot.move_toward(target, step)
			step = 0.0
	return _carrot
