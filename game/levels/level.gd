class_name Level
extends Node2D
## The contract every level follows: a [Node2D] whose child named [code]Player[/code] is
## the avatar, with a start, a goal, collectibles and an autopilot path.
##
## Optional children the default implementation understands:
## [code]Start[/code] ([Node2D], usually a [Marker2D]: the spawn point; without it the
## player's position when the level became ready) and [code]AutopilotPath[/code] (a
## [Line2D] or [Path2D] whose points, in its own space, lead from the start to the goal).
## Subclasses that override [method _ready] need not call [code]super()[/code]: the player
## is found and wired by an [code]@onready[/code] initializer, which runs before any
## [code]_ready[/code] body.

## Emitted once when the player reaches the goal.
signal goal_reached
## Emitted when the player picks up an item: [param collected] so far out of [param total].
signal item_collected(collected: int, total: int)
## Relay of [signal Player.bumped]: the player began touching [param collider]; the normal
## points from the touched surface toward the player; [param speed] in pixels/second.
signal player_bumped(collider: Object, normal: Vector2, speed: float)

## Whether [signal goal_reached] has been emitted.
var is_goal_reached: bool = false

var _spawn_position: Vector2 = Vector2.ZERO

## The avatar: the child named [code]Player[/code] (null if the level has none).
@onready var player: Player = _bind_player()


## World-space waypoints from the start to the goal: a follower that steers toward each in
## turn (moving on within about 28 px of it) reaches the goal without getting stuck. The
## game itself never follows them; test drivers' autopilots do.
func get_autopilot_path() -> PackedVector2Array:
	var path_node: Node = get_node_or_null(^"AutopilotPath")
	var points: PackedVector2Array = PackedVector2Array()
	if path_node is Line2D:
		var line: Line2D = path_node
		for point: Vector2 in line.points:
			points.append(line.to_global(point))
	elif path_node is Path2D:
		var path: Path2D = path_node
		if path.curve != null:
			for i: int in path.curve.point_count:
				points.append(path.to_global(path.curve.get_point_position(i)))
	if points.is_empty():
		points.append(get_spawn_position())
	return points


## How many items (pearls, …) the level holds; 0 when it has none to collect.
func get_item_total() -> int:
	return 0


## World-space position where the player starts.
func get_spawn_position() -> Vector2:
	var start: Node = get_node_or_null(^"Start")
	if start is Node2D:
		return (start as Node2D).global_position
	return _spawn_position


## Emits [signal goal_reached], once per level instance; later calls do nothing.
func reach_goal() -> void:
	if is_goal_reached:
		return
	is_goal_reached = true
	goal_reached.emit()


## Emits [signal item_collected] with the running count out of [param total].
func report_item_collected(collected: int, total: int) -> void:
	item_collected.emit(collected, total)


func _bind_player() -> Player:
	var found: Player = get_node_or_null(^"Player") as Player
	if found == null:
		return null
	_spawn_position = found.global_position
	if not found.bumped.is_connected(_relay_player_bumped):
		found.bumped.connect(_relay_player_bumped)
	return found


func _relay_player_bumped(collider: Object, normal: Vector2, speed: float) -> void:
	player_bumped.emit(collider, normal, speed)
