class_name StudyLevel
extends Level
## A level of the maze study (the evaluation maze and the demonstration levels), following
## the [Level] contract: [code]Player[/code], [code]Start[/code] (a [Marker2D]),
## [code]AutopilotPath[/code] (a [Line2D] from the start to the goal, for the scripted
## participant), plus [code]Walls[/code] ([MazeWalls]: static bodies whose collision
## polygons are drawn and handed to the constraint renderer) and [code]Goal[/code]
## ([StudyGoal]). It draws its floor and the start pad itself.
## [br][br]
## Maze units, as the constraint renderer and the telemetry use them, are this node's own
## pixels: keep the level's root at the origin, unscaled.

## Id written to trials.csv ([code][A-Za-z0-9][A-Za-z0-9_.-]*[/code]).
@export var level_id: String = "maze"
## Short name shown during practice.
@export var title: String = "Maze"
## The playing area in level pixels: what the camera shows and what the device's workspace
## maps onto in position control. Empty: the box around the walls.
@export var bounds: Rect2 = Rect2():
	set(value):
		bounds = value
		queue_redraw()
@export var floor_color: Color = Color(0.05, 0.13, 0.2):
	set(value):
		floor_color = value
		queue_redraw()
## Colour of the start pad and the floor grid.
@export var marking_color: Color = Color(0.56, 0.78, 0.88, 0.35):
	set(value):
		marking_color = value
		queue_redraw()
## Spacing of the floor grid, pixels (0: no grid).
@export var grid_spacing: float = 60.0:
	set(value):
		grid_spacing = value
		queue_redraw()


func _ready() -> void:
	# The sub's headlight belongs to the side-scroller; in a maze seen from above it only
	# distracts.
	var beam: CanvasItem = get_node_or_null(^"Player/Visual/Beam") as CanvasItem
	if beam != null:
		beam.hide()
	var goal: StudyGoal = get_goal()
	if goal != null and not goal.reached.is_connected(reach_goal):
		goal.reached.connect(reach_goal)


## The wall bodies (children of [code]Walls[/code], or [code]Walls[/code] itself).
func get_walls() -> Array[Node]:
	var walls: Node = get_node_or_null(^"Walls")
	var out: Array[Node] = []
	if walls != null:
		out.append(walls)
	return out


## The walls' outlines as point pairs in maze units (see [WallSegments]).
func get_wall_segments() -> PackedVector2Array:
	return WallSegments.extract(get_walls(), self)


## The playing area in maze units: [member bounds], or the box around the walls.
func get_bounds() -> Rect2:
	if bounds.has_area():
		return bounds
	return WallSegments.bounds_of(get_wall_segments())


## The goal, or null.
func get_goal() -> StudyGoal:
	return get_node_or_null(^"Goal") as StudyGoal


## Arms the goal again and clears [member Level.is_goal_reached] (practice restarts).
func reset_goal() -> void:
	is_goal_reached = false
	var goal: StudyGoal = get_goal()
	if goal != null:
		goal.reset()


func _draw() -> void:
	var area: Rect2 = get_bounds()
	if not area.has_area():
		return
	draw_rect(area, floor_color)
	if grid_spacing > 1.0:
		var line_color: Color = Color(marking_color, marking_color.a * 0.25)
		var x: float = area.position.x + grid_spacing
		while x < area.end.x:
			draw_line(Vector2(x, area.position.y), Vector2(x, area.end.y), line_color, 1.0)
			x += grid_spacing
		var y: float = area.position.y + grid_spacing
		while y < area.end.y:
			draw_line(Vector2(area.position.x, y), Vector2(area.end.x, y), line_color, 1.0)
			y += grid_spacing
	var start: Node2D = get_node_or_null(^"Start") as Node2D
	if start != null:
		draw_circle(start.position, 30.0, Color(marking_color, marking_color.a * 0.5))
		draw_arc(start.position, 30.0, 0.0, TAU, 40, marking_color, 2.0, true)
