extends RefCounted
## A study level's walls as plain polygons, to check recorded positions against: how far a
## point is from the nearest wall (negative inside one), and which way the wall's surface
## faces it there. Independent of the game's own code (the physics, [WallSegments]).

## Two unit normals closer than this are the same surface.
const SAME_NORMAL: float = 0.05

## The walls, each a closed polygon in level pixels.
var polygons: Array[PackedVector2Array] = []


## Reads the walls of [param scene] (a [StudyLevel] whose root is at the origin): every
## CollisionPolygon2D under its [code]Walls[/code], through their local transforms. The
## level is instantiated but never enters the tree (its player would submit frames).
func read_level(scene: PackedScene) -> void:
	var level: Node = scene.instantiate()
	var walls: Node2D = level.get_node(^"Walls") as Node2D
	for child: Node in walls.get_children():
		var polygon: CollisionPolygon2D = child as CollisionPolygon2D
		if polygon != null:
			var xform: Transform2D = walls.transform * polygon.transform
			polygons.append(xform * polygon.polygon)
	level.free()


## Whether [param point] lies inside a wall.
func is_inside(point: Vector2) -> bool:
	for polygon: PackedVector2Array in polygons:
		if Geometry2D.is_point_in_polygon(point, polygon):
			return true
	return false


## Distance from [param point] to the nearest wall surface (negative inside a wall).
func distance(point: Vector2) -> float:
	var best: float = INF
	for polygon: PackedVector2Array in polygons:
		for i: int in polygon.size():
			var closest: Vector2 = Geometry2D.get_closest_point_to_segment(
				point, polygon[i], polygon[(i + 1) % polygon.size()]
			)
			best = minf(best, point.distance_to(closest))
	return -best if is_inside(point) else best


## The unit normals (from the wall toward [param point]) of the surfaces within
## [param reach] of it, one per distinct direction: empty in the open, one against a single
## wall, two or more in a corner.
func normals_within(point: Vector2, reach: float) -> Array[Vector2]:
	var out: Array[Vector2] = []
	if is_inside(point):
		return out
	for polygon: PackedVector2Array in polygons:
		for i: int in polygon.size():
			var closest: Vector2 = Geometry2D.get_closest_point_to_segment(
				point, polygon[i], polygon[(i + 1) % polygon.size()]
			)
			var away: Vector2 = point - closest
			if away.length() > reach or away.is_zero_approx():
				continue
			var normal: Vector2 = away.normalized()
			var known: bool = false
			for other: Vector2 in out:
				known = known or other.distance_to(normal) < SAME_NORMAL
			if not known:
				out.append(normal)
	return out
