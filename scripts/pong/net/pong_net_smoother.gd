class_name PongNetSmoother
extends RefCounted
## How a follower brings its own ball (simulated by its servo) onto the master's.
##
## Each received state is extrapolated to "now" on the follower with the same ballistic
## model the computer player uses ([PongPredictor]: gravity and bounces) over its estimated
## age. The velocity and spin are taken at once (no visible jump: positions stay
## continuous), the position error is blended out exponentially with time constant
## [member tau_s] (95 % gone after 3 tau, about 120 ms), unless it is larger than
## [member snap_distance_m] (a serve, a missed hand-off): then the ball is put there.
## Each correction's size is recorded for the report.

## Time constant of the position blend, seconds.
var tau_s: float = 0.04
## Larger errors are not blended but snapped, metres.
var snap_distance_m: float = 2.5
## Position error not yet blended out, metres (world).
var pending: Vector3 = Vector3.ZERO
## The size of each received correction, metres (before blending).
var sizes: PackedFloat32Array = PackedFloat32Array()
## Snaps made.
var snaps: int = 0


## The master's state ([param position], [param velocity]) [param age_s] seconds later,
## by [param predictor] under gravity [param g].
static func extrapolate(
	predictor: PongPredictor, position: Vector3, velocity: Vector3, g: float, age_s: float
) -> Array[Vector3]:
	if age_s <= 0.0:
		return [position, velocity]
	var path: Array[PongPredictor.Segment] = predictor.path(position, velocity, g, age_s)
	return [PongPredictor.position_at(path, age_s), PongPredictor.velocity_at(path, age_s)]


## A new target: the master's ball extrapolated to now is [param target]; ours is at
## [param local]. Returns true when the ball is to be snapped to [param target].
func on_target(local: Vector3, target: Vector3) -> bool:
	var error: Vector3 = target - local
	sizes.append(error.length())
	if error.length() > snap_distance_m:
		snaps += 1
		pending = Vector3.ZERO
		return true
	pending = error
	return false


## The part of the pending error to apply over the next [param dt] seconds.
func take(dt: float) -> Vector3:
	var part: Vector3 = pending * (1.0 - exp(-maxf(dt, 0.0) / tau_s))
	pending -= part
	return part


## The [param q] quantile (0..1) of [param values] (0 when empty).
static func quantile(values: PackedFloat32Array, q: float) -> float:
	if values.is_empty():
		return 0.0
	var sorted: PackedFloat32Array = values.duplicate()
	sorted.sort()
	var index: int = clampi(ceili(q * sorted.size()) - 1, 0, sorted.size() - 1)
	return sorted[index]
