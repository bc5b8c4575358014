class_name PongPredictor
extends RefCounted
## The computer player's model of where the ball goes: parabolas under gravity, reflected
## by the floor, walls and ceiling with the court's restitution. It is a prediction, not
## the simulation (that runs in the servo): no spin, no air friction, no contact with
## paddles. A path is a list of segments, each a parabola from one bounce to the next.


## A flight between two bounces, from [member start] on:
## [code]p(t) = position + velocity (t - start) - (0, gravity, 0) (t - start)² / 2[/code].
class Segment:
	extends RefCounted
	var start: float = 0.0
	var position: Vector3 = Vector3.ZERO
	var velocity: Vector3 = Vector3.ZERO
	## Gravity along -y, m/s² (0 once the ball rolls, and in beginner mode).
	var gravity: float = 0.0
	## What ends the segment: "floor", "wall" (sides, back walls, ceiling) or "" (horizon).
	var ends_with: String = ""

	func _init(p_start: float, p_position: Vector3, p_velocity: Vector3, p_gravity: float) -> void:
		start = p_start
		position = p_position
		velocity = p_velocity
		gravity = p_gravity

	func position_at(t: float) -> Vector3:
		return PongPredictor.parabola_at(position, velocity, gravity, t - start)

	func velocity_at(t: float) -> Vector3:
		return velocity + Vector3(0.0, -gravity * (t - start), 0.0)


## Bounces followed at most per path.
const MAX_BOUNCES: int = 12
## Slower vertical bounces than this end the path's bouncing (the ball rolls), m/s.
const ROLLING_SPEED_M_PER_S: float = 0.3

var _court: PongCourt = null


func _init(court: PongCourt) -> void:
	_court = court


## The closed form of one flight: position after [param t] seconds from [param position]
## at [param velocity] under gravity [param g] (m/s², along -y).
static func parabola_at(position: Vector3, velocity: Vector3, g: float, t: float) -> Vector3:
	return position + velocity * t + Vector3(0.0, -0.5 * g * t * t, 0.0)


## The ball's predicted path for [param horizon] seconds from now (t = 0), under gravity
## [param g] (0 in beginner mode).
func path(position: Vector3, velocity: Vector3, g: float, horizon: float) -> Array[Segment]:
	var segments: Array[Segment] = []
	var segment: Segment = Segment.new(0.0, position, velocity, g)
	segments.append(segment)
	var r: float = _court.ball_radius
	var low: Vector3 = Vector3(-_court.half_width + r, r, -_court.half_length + r)
	var high: Vector3 = Vector3(
		_court.half_width - r, _court.wall_height - r, _court.half_length - r
	)
	for bounce: int in MAX_BOUNCES:
		var hit: Vector2 = _next_hit(segment, low, high)
		var t_hit: float = segment.start + hit.x
		if t_hit >= horizon:
			break
		var axis: int = int(hit.y)
		var at: Vector3 = segment.position_at(t_hit)
		var v: Vector3 = segment.velocity_at(t_hit)
		var floor_hit: bool = axis == Vector3.AXIS_Y and v.y < 0.0
		segment.ends_with = "floor" if floor_hit else "wall"
		v[axis] = -v[axis] * (_court.restitution_court if floor_hit else _court.restitution_wall)
		var g_next: float = segment.gravity
		if floor_hit and absf(v.y) < ROLLING_SPEED_M_PER_S:
			v.y = 0.0
			g_next = 0.0
		at[axis] = clampf(at[axis], low[axis], high[axis])
		segment = Segment.new(t_hit, at, v, g_next)
		segments.append(segment)
	return segments


## The predicted position at time [param t] on [param segments] (from [method path]).
static func position_at(segments: Array[Segment], t: float) -> Vector3:
	return _segment_at(segments, t).position_at(t)


## The predicted velocity at time [param t] on [param segments].
static func velocity_at(segments: Array[Segment], t: float) -> Vector3:
	return _segment_at(segments, t).velocity_at(t)


## When the path first touches the floor in [param player]'s territory of a court of
## [param count] players (-1: not within the path).
static func first_floor_time_in(segments: Array[Segment], player: int, count: int = 2) -> float:
	for i: int in segments.size() - 1:
		if segments[i].ends_with == "floor":
			var next: Segment = segments[i + 1]
			if PongCourt.territory_of(next.position, count) == player:
				return next.start
	return -1.0


static func _segment_at(segments: Array[Segment], t: float) -> Segment:
	var found: Segment = segments[0]
	for segment: Segment in segments:
		if segment.start <= t:
			found = segment
	return found


# The first plane the ball's centre reaches: (seconds, axis); seconds INF when none.
static func _next_hit(segment: Segment, low: Vector3, high: Vector3) -> Vector2:
	var best: Vector2 = Vector2(INF, -1)
	for axis: int in [Vector3.AXIS_X, Vector3.AXIS_Z]:
		var v: float = segment.velocity[axis]
		if v > 1e-9:
			best = _earlier(best, (high[axis] - segment.position[axis]) / v, axis)
		elif v < -1e-9:
			best = _earlier(best, (low[axis] - segment.position[axis]) / v, axis)
	var a: float = -0.5 * segment.gravity
	var vy: float = segment.velocity.y
	var y: float = segment.position.y
	best = _earlier(best, _first_root(a, vy, y - low.y, -1.0), Vector3.AXIS_Y)
	return _earlier(best, _first_root(a, vy, y - high.y, 1.0), Vector3.AXIS_Y)


static func _earlier(best: Vector2, dt: float, axis: int) -> Vector2:
	return Vector2(dt, axis) if dt > 1e-6 and dt < best.x else best


# Smallest t > 0 with a t² + b t + c = 0 where the height crosses the plane moving in
# [param direction] (-1 down onto the floor, +1 up into the ceiling); INF when none.
static func _first_root(a: float, b: float, c: float, direction: float) -> float:
	var roots: Array[float] = []
	if absf(a) < 1e-12:
		if absf(b) > 1e-12:
			roots.append(-c / b)
	else:
		var disc: float = b * b - 4.0 * a * c
		if disc >= 0.0:
			var s: float = sqrt(disc)
			roots.append((-b - s) / (2.0 * a))
			roots.append((-b + s) / (2.0 * a))
	var best: float = INF
	for t: float in roots:
		var vy: float = 2.0 * a * t + b
		if t > 1e-6 and vy * direction > 0.0 and t < best:
			best = t
	return best
