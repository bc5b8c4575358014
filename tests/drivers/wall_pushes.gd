class_name WallPushes
extends RefCounted
## The part of the scripted participant that touches the walls (see
## [member StudyPilot.touch_walls]): from the level's start, before heading for the goal, it
## pushes into the nearest wall along each of [member pushes] and turns away from it, then
## comes back to the start for the next one.
## [br][br]
## Acceleration control: the hand drives the avatar along the heading until it touches a
## wall, presses at the push's angle to the heading (0 straight in; ±30° slides along the
## wall), then is pulled straight back (the input turns away from the wall: the release that
## the paper's summed-normal model answers with a pull for as long as the contact lasts),
## and steers the avatar back to the start.
## Position control: the hand goes [constant BEYOND_PX] through the wall at the push's angle
## (the proxy must stay on the near side), holds there, and comes back.

## What the script is doing with the current push.
enum Phase { APPROACH, PRESS, RELEASE, RETURN }

## Deflection of the hand while pushing (input vector length, acceleration control).
const STRENGTH: float = 0.8
## Longest approach before pressing anyway, seconds.
const APPROACH_MAX_S: float = 2.0
## Time pressed into the wall at the push's angle, seconds.
const PRESS_S: float = 0.3
## Time the hand pulls straight away from the wall before steering home, seconds.
const RELEASE_S: float = 0.15
## Longest way back to the start, seconds.
const RETURN_MAX_S: float = 3.0
## Back at the start: this close (level pixels) ...
const HOME_PX: float = 6.0
## ... and this slow (px/s, acceleration control).
const HOME_SPEED: float = 40.0
## Position control: how far past the wall's face the hand goes, level pixels.
const BEYOND_PX: float = 60.0
## Position control: the hand's reach when no wall lies along the push, level pixels.
const REACH_PX: float = 150.0

## Each push: x, y the heading (a unit vector in level axes), z the angle of the press to
## it in degrees (positive: clockwise on screen).
var pushes: Array[Vector3] = [
	Vector3(1.0, 0.0, 0.0),
	Vector3(1.0, 0.0, 30.0),
	Vector3(1.0, 0.0, -30.0),
	Vector3(-1.0, 0.0, 0.0),
	Vector3(-1.0, 0.0, 30.0),
	Vector3(-1.0, 0.0, -30.0),
	Vector3(0.0, 1.0, 0.0),
]
## The push under way (its index in [member pushes]).
var index: int = 0
var phase: Phase = Phase.APPROACH
## Releases done so far (acceleration control: the hand turned away from a wall it touched).
var releases: int = 0
## Speed of the hand's target point in position control, level pixels per second.
var speed: float = 260.0

var _elapsed: float = 0.0
var _carrot: Vector2 = Vector2.INF
var _target: Vector2 = Vector2.ZERO
var _home: Autopilot = null


func _init(p_speed: float = 260.0) -> void:
	speed = p_speed


## Whether every push is done.
func is_finished() -> bool:
	return index >= pushes.size()


## The hand target for this tick (normalised, game axes).
func steer(rig: ConditionRig, delta: float) -> Vector2:
	if is_finished():
		return rig.start_hand()
	_elapsed += delta
	var push: Vector3 = pushes[index]
	var heading: Vector2 = Vector2(push.x, push.y).normalized()
	var pressing: Vector2 = heading.rotated(deg_to_rad(push.z))
	if StudyFormat.is_position_control(rig.condition):
		return _steer_position(rig, pressing, delta)
	return _steer_acceleration(rig, heading, pressing, delta)


func _steer_acceleration(
	rig: ConditionRig, heading: Vector2, pressing: Vector2, delta: float
) -> Vector2:
	var player: Player = rig.player
	match phase:
		Phase.APPROACH:
			if player.get_slide_collision_count() > 0 or _elapsed >= APPROACH_MAX_S:
				_next(Phase.PRESS)
			return heading * STRENGTH
		Phase.PRESS:
			if _elapsed >= PRESS_S:
				releases += 1
				_next(Phase.RELEASE)
			return pressing * STRENGTH
		Phase.RELEASE:
			if _elapsed >= RELEASE_S:
				_home = Autopilot.new(PackedVector2Array([rig.level.get_spawn_position()]))
				_home.reach_radius = HOME_PX * 0.5
				_next(Phase.RETURN)
			return -heading * STRENGTH
	var start: Vector2 = rig.level.get_spawn_position()
	var home: bool = (
		player.global_position.distance_to(start) < HOME_PX
		and player.velocity.length() < HOME_SPEED
	)
	if home or _elapsed >= RETURN_MAX_S:
		_next_push()
		return Vector2.ZERO
	return _home.steer(
		player.global_position, player.velocity, player.max_speed, player.acceleration, delta
	)


func _steer_position(rig: ConditionRig, pressing: Vector2, delta: float) -> Vector2:
	var start: Vector2 = rig.level.get_spawn_position()
	if _carrot == Vector2.INF:
		_carrot = start
		_target = _through_wall(rig, start, pressing)
	match phase:
		Phase.APPROACH:
			_carrot = _carrot.move_toward(_target, speed * delta)
			if _carrot == _target:
				_next(Phase.PRESS)
		Phase.PRESS:
			if _elapsed >= PRESS_S:
				_next(Phase.RETURN)
		_:
			_carrot = _carrot.move_toward(start, speed * delta)
			var home: bool = rig.avatar_position().distance_to(start) < HOME_PX
			if (_carrot == start and home) or _elapsed >= RETURN_MAX_S:
				_next_push()
				return rig.map.hand_of(start)
	return rig.map.hand_of(_carrot)


# The point BEYOND_PX past the first wall along [param direction] from [param from] (or
# REACH_PX away when there is none).
func _through_wall(rig: ConditionRig, from: Vector2, direction: Vector2) -> Vector2:
	var exclude: Array[RID] = [rig.player.get_rid()]
	var query: PhysicsRayQueryParameters2D = PhysicsRayQueryParameters2D.create(
		from, from + direction * 4.0 * REACH_PX, rig.player.collision_mask, exclude
	)
	var space: PhysicsDirectSpaceState2D = rig.level.get_world_2d().direct_space_state
	var hit: Dictionary = space.intersect_ray(query)
	if hit.is_empty():
		return from + direction * REACH_PX
	var point: Vector2 = hit["position"]
	return point + direction * BEYOND_PX


func _next(next_phase: Phase) -> void:
	phase = next_phase
	_elapsed = 0.0


func _next_push() -> void:
	index += 1
	_carrot = Vector2.INF
	_next(Phase.APPROACH)
