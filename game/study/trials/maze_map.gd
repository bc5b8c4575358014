class_name MazeMap
extends HapticMazeMapping
## Position control's map between the maze (level pixels, y down) and the device's
## workspace: the [HapticMazeMapping] the native constraint renderer is handed, resolved
## the same way ([code]gdextension/src/renderers/constraint/maze_mapping.h[/code]).
## [br][br]
## "Hand" positions are normalised like [code]Haptics.device.set_hand_target[/code]'s: metres over
## the device's workspace radius, game axes (x right, y down).

## The device's workspace radius, metres.
var device_radius_m: float = 0.1
## The maze rectangle, maze units (y down).
var bounds: Rect2:
	get:
		return Rect2(maze_min, maze_max - maze_min)


## [param p_workspace]: [code]disc[/code] or [code]square[/code]
## ([constant HapticConstraintFacts.WORKSPACE_SHAPE_NAMES]).
func _init(
	p_bounds: Rect2 = Rect2(0.0, 0.0, 1.0, 1.0),
	p_workspace: String = "disc",
	p_half_extent_m: float = 0.0,
	p_device_radius_m: float = 0.1
) -> void:
	maze_min = p_bounds.position
	maze_max = p_bounds.end
	var shape: int = maxi(HapticConstraintFacts.WORKSPACE_SHAPE_NAMES.find(p_workspace), 0)
	workspace_shape = shape as HapticConstraintFacts.WorkspaceShape
	workspace_half_extent_m = p_half_extent_m
	device_radius_m = p_device_radius_m


## Metres of device travel per maze unit.
func metres_per_unit() -> float:
	var half: float = workspace_half_extent_m if workspace_half_extent_m > 0.0 else device_radius_m
	var disc: bool = workspace_shape == HapticConstraintFacts.WorkspaceShape.DISC
	var span: float = bounds.size.length() if disc else maxf(bounds.size.x, bounds.size.y)
	return 2.0 * half / maxf(span, 1e-9)


## The normalised hand position that puts the device on maze point [param point].
func hand_of(point: Vector2) -> Vector2:
	return (point - bounds.get_center()) * metres_per_unit() / maxf(device_radius_m, 1e-9)


## The maze point under the normalised hand position [param hand].
func point_of_hand(hand: Vector2) -> Vector2:
	return bounds.get_center() + hand * device_radius_m / metres_per_unit()


## The maze point of a device position given in metres, game axes.
func point_of_metres(metres: Vector2) -> Vector2:
	return bounds.get_center() + metres / metres_per_unit()
