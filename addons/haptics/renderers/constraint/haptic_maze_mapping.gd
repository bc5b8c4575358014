class_name HapticMazeMapping
extends RefCounted
## How a maze maps onto the device's workspace for the constraint renderer
## ([code]Haptics.set_constraint_geometry[/code]): one scale for both axes, chosen so the
## maze rectangle fits the workspace shape (disc: its diagonal spans the diameter; square:
## its longer side does), the maze centre on the workspace centre.

## The maze rectangle, maze units (y down).
var bounds: Rect2 = Rect2(0.0, 0.0, 1.0, 1.0)
## [code]disc[/code] or [code]square[/code].
var workspace: String = "disc"
## Half extent of the workspace the maze maps onto, metres (0: the device's radius).
var half_extent_m: float = 0.0


func _init(
	p_bounds: Rect2 = Rect2(0.0, 0.0, 1.0, 1.0),
	p_workspace: String = "disc",
	p_half_extent_m: float = 0.0
) -> void:
	bounds = p_bounds
	workspace = p_workspace
	half_extent_m = p_half_extent_m


## The mapping dictionary [code]HapticsServer.set_constraint_geometry[/code] takes.
func to_dictionary() -> Dictionary:
	return {
		"maze_min": bounds.position,
		"maze_max": bounds.end,
		"workspace": workspace,
		"half_extent_m": half_extent_m,
	}
