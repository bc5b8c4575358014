@tool
class_name MazeWalls
extends StaticBody2D
## The walls of a study level: a [StaticBody2D] whose [CollisionPolygon2D] and
## [CollisionShape2D] children are both what the avatar collides with and what is drawn,
## so a maze is edited in one place (move a polygon's points in the editor and the picture
## follows). The constraint renderer gets the same outlines through [WallSegments].

@export var fill_color: Color = Color(0.2, 0.45, 0.55):
	set(value):
		fill_color = value
		queue_redraw()
@export var edge_color: Color = Color(0.55, 0.85, 0.9):
	set(value):
		edge_color = value
		queue_redraw()
## Width of the outline, pixels.
@export_range(0.0, 8.0, 0.5) var edge_width: float = 2.0:
	set(value):
		edge_width = value
		queue_redraw()


func _ready() -> void:
	collision_layer = 1
	collision_mask = 0
	queue_redraw()


func _draw() -> void:
	for child: Node in get_children():
		if child is CollisionPolygon2D:
			var polygon: CollisionPolygon2D = child
			_draw_outline(polygon.transform, polygon.polygon)
		elif child is CollisionShape2D:
			_draw_shape(child as CollisionShape2D)


func _draw_shape(holder: CollisionShape2D) -> void:
	var shape: Shape2D = holder.shape
	if shape is CircleShape2D:
		var radius: float = (shape as CircleShape2D).radius
		draw_circle(holder.position, radius, fill_color)
		if edge_width > 0.0:
			draw_arc(holder.position, radius, 0.0, TAU, 48, edge_color, edge_width, true)
	elif shape is RectangleShape2D:
		var half: Vector2 = (shape as RectangleShape2D).size * 0.5
		var points: PackedVector2Array = [
			-half, Vector2(half.x, -half.y), half, Vector2(-half.x, half.y)
		]
		_draw_outline(holder.transform, points)
	elif shape is ConvexPolygonShape2D:
		_draw_outline(holder.transform, (shape as ConvexPolygonShape2D).points)


func _draw_outline(xform: Transform2D, local_points: PackedVector2Array) -> void:
	if local_points.size() < 3:
		return
	var points: PackedVector2Array = xform * local_points
	if not Geometry2D.triangulate_polygon(points).is_empty():
		draw_colored_polygon(points, fill_color)
	if edge_width > 0.0:
		var loop: PackedVector2Array = points.duplicate()
		loop.append(points[0])
		draw_polyline(loop, edge_color, edge_width, true)
