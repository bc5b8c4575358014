class_name WallSegments
extends RefCounted
## Extracts the outline segments of a level's static walls for the constraint renderer
## ([code]HapticsConstraint.set_walls[/code]): every edge of every
## [CollisionPolygon2D] and [CollisionShape2D] under the given nodes, as consecutive point
## pairs [code]a0, b0, a1, b1, …[/code] in the coordinates of a reference [Node2D] (the
## level: maze units are the level's own pixels).
##
## Polygons are closed loops in both build modes (as Godot builds them). Rectangles,
## convex and concave polygons and segments are exact; circles and capsules become
## [constant ARC_SEGMENTS]-gons around their outline. Disabled shapes are skipped.

## Segments per full circle when a round shape is approximated.
const ARC_SEGMENTS: int = 24


## The segments of every collision shape under [param roots] (each a node or subtree), in
## [param space]'s coordinates.
static func extract(roots: Array[Node], space: Node2D) -> PackedVector2Array:
	var out: PackedVector2Array = PackedVector2Array()
	var to_space: Transform2D = space.get_global_transform().affine_inverse()
	for root: Node in roots:
		_collect(root, to_space, out)
	return out


## The axis-aligned box around [param segments] (empty when there are none).
static func bounds_of(segments: PackedVector2Array) -> Rect2:
	if segments.is_empty():
		return Rect2()
	var box: Rect2 = Rect2(segments[0], Vector2.ZERO)
	for point: Vector2 in segments:
		box = box.expand(point)
	return box


static func _collect(node: Node, to_space: Transform2D, out: PackedVector2Array) -> void:
	if node is CollisionPolygon2D:
		var polygon: CollisionPolygon2D = node
		if not polygon.disabled:
			_add_loop(polygon.polygon, to_space * polygon.get_global_transform(), out)
	elif node is CollisionShape2D:
		var holder: CollisionShape2D = node
		if not holder.disabled and holder.shape != null:
			_add_shape(holder.shape, to_space * holder.get_global_transform(), out)
	for child: Node in node.get_children():
		_collect(child, to_space, out)


static func _add_shape(shape: Shape2D, xform: Transform2D, out: PackedVector2Array) -> void:
	if shape is RectangleShape2D:
		var half: Vector2 = (shape as RectangleShape2D).size * 0.5
		_add_loop(
			PackedVector2Array([-half, Vector2(half.x, -half.y), half, Vector2(-half.x, half.y)]),
			xform,
			out
		)
	elif shape is ConvexPolygonShape2D:
		_add_loop((shape as ConvexPolygonShape2D).points, xform, out)
	elif shape is ConcavePolygonShape2D:
		for point: Vector2 in (shape as ConcavePolygonShape2D).segments:
			out.append(xform * point)
	elif shape is SegmentShape2D:
		var segment: SegmentShape2D = shape
		out.append(xform * segment.a)
		out.append(xform * segment.b)
	elif shape is CircleShape2D:
		_add_loop(_arc(Vector2.ZERO, (shape as CircleShape2D).radius, 0.0, TAU), xform, out)
	elif shape is CapsuleShape2D:
		var capsule: CapsuleShape2D = shape
		var offset: float = maxf(0.0, capsule.height * 0.5 - capsule.radius)
		var points: PackedVector2Array = _arc(Vector2(0.0, -offset), capsule.radius, PI, TAU)
		points.append_array(_arc(Vector2(0.0, offset), capsule.radius, 0.0, PI))
		_add_loop(points, xform, out)
	else:
		push_warning("WallSegments: %s is not supported; skipped." % shape.get_class())


static func _arc(centre: Vector2, radius: float, from: float, to: float) -> PackedVector2Array:
	var steps: int = maxi(2, ceili(ARC_SEGMENTS * (to - from) / TAU))
	var points: PackedVector2Array = PackedVector2Array()
	for i: int in steps + (0 if is_equal_approx(to - from, TAU) else 1):
		var angle: float = from + (to - from) * i / steps
		points.append(centre + Vector2(cos(angle), sin(angle)) * radius)
	return points


static func _add_loop(
	points: PackedVector2Array, xform: Transform2D, out: PackedVector2Array
) -> void:
	var count: int = points.size()
	if count < 2:
		return
	for i: int in count:
		var a: Vector2 = xform * points[i]
		var b: Vector2 = xform * points[(i + 1) % count]
		if not a.is_equal_approx(b):
			out.append(a)
			out.append(b)
