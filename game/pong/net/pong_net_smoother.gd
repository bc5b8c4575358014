class_name PongNetSmoother
extends RefCounted
## How a follower brings its own ball (simulated by its servo) onto the master's: the
## prediction and the bookkeeping. The blend itself is the servo's (CORRECT_BALL, its
## [code]pong.correction_*[/code] settings): the velocity and spin are taken at once, the
## position error is blended out with a 40 ms time constant at 20 m/s at most, so the ball
## never jumps (it moves at most 38 mm in a 1 ms tick because of a correction), and near the
## local player's paddle no faster than the hand's force may change (the slew rate).
##
## Each played state is extrapolated to "now" on the follower with the same ballistic model
## the computer player uses ([PongPredictor]: gravity and bounces) over its estimated age.
## Each correction's size is recorded for the report.

## The size of each correction, metres (before blending).
var sizes: PackedFloat32Array = PackedFloat32Array()
## Corrections put at once instead of blended. The servo blends every correction now,
## however large (a serve is no correction), so this stays 0; the report keeps the count so
## runs before and after compare.
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


## A correction from our ball at [param local] to [param target]: its size is recorded.
func record(local: Vector3, target: Vector3) -> void:
	sizes.append((target - local).length())


## The [param q] quantile (0..1) of [param values] (0 when empty).
static func quantile(values: PackedFloat32Array, q: float) -> float:
	if values.is_empty():
		return 0.0
	var sorted: PackedFloat32Array = values.duplicate()
	sorted.sort()
	var index: int = clampi(ceili(q * sorted.size()) - 1, 0, sorted.size() - 1)
	return sorted[index]
