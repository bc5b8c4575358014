class_name Autopilot
extends RefCounted
## Steers a [Player] along waypoints (for instance [method Level.get_autopilot_path]): each
## tick it returns the input vector that accelerates the body toward the current waypoint,
## braking so it arrives without overshooting, and moves on when close enough.

## World-space waypoints, followed in order.
var path: PackedVector2Array = PackedVector2Array()
## Index of the waypoint being steered to; equals the path's size when finished.
var index: int = 0
## Distance (pixels) at which a waypoint counts as reached.
var reach_radius: float = 28.0


func _init(p_path: PackedVector2Array = PackedVector2Array()) -> void:
	path = p_path


## Whether every waypoint has been reached.
func is_finished() -> bool:
	return index >= path.size()


## The input vector (length ≤ 1) for a body at [param position] moving at [param velocity]
## with the given top speed and acceleration (pixels/s, pixels/s²), for a tick of
## [param delta] seconds.
func steer(
	position: Vector2, velocity: Vector2, max_speed: float, acceleration: float, delta: float
) -> Vector2:
	while index < path.size() and position.distance_to(path[index]) < reach_radius:
		index += 1
	if is_finished():
		return Vector2.ZERO
	var to_target: Vector2 = path[index] - position
	var distance: float = to_target.length()
	# Cut the corner toward the next waypoint when there is one; stop at the last.
	var cruise: float = max_speed
	if index == path.size() - 1:
		cruise = minf(max_speed, sqrt(2.0 * acceleration * 0.5 * distance))
	var desired: Vector2 = to_target / maxf(distance, 0.001) * cruise
	return ((desired - velocity) / maxf(acceleration * delta, 0.001)).limit_length(1.0)


## Steers [param player] for one tick: sets its [member Player.input_vector].
func drive(player: Player, delta: float) -> void:
	var top: float = player.max_speed * (player.water_speed_factor if player.in_water else 1.0)
	player.input_vector = steer(
		player.global_position, player.velocity, top, player.acceleration, delta
	)
