@tool
class_name Terrain
extends StaticBody2D
## Static ground of one material. Each [CollisionPolygon2D] child is both a collider and,
## drawn at load (also in the editor), a textured [Polygon2D] with a rim [Line2D], so a
## level only lays out collision polygons and picks a style.
##
## [member haptic_material] is what the haptic probe feels (see [method HapticMaterial.of]).

const _GENERATED_PREFIX: String = "_Drawn"

## How this ground feels: stiffness, friction and the transient of impacts on it.
@export var haptic_material: HapticMaterial:
	set(value):
		haptic_material = value
		if value != null:
			set_meta(&"haptic_material", value)
## Tiled fill texture.
@export var fill_texture: Texture2D:
	set(value):
		fill_texture = value
		_rebuild()
@export var fill_color: Color = Color.WHITE:
	set(value):
		fill_color = value
		_rebuild()
## Colour of the rim drawn along every edge.
@export var edge_color: Color = Color(0.1, 0.12, 0.16):
	set(value):
		edge_color = value
		_rebuild()
## Width of the rim, in pixels (0: no rim).
@export var edge_width: float = 6.0:
	set(value):
		edge_width = value
		_rebuild()
## Colour of the lip drawn just inside edges that face up (transparent: none).
@export var highlight_color: Color = Color(1.0, 1.0, 1.0, 0.0):
	set(value):
		highlight_color = value
		_rebuild()
## Colour of the shade drawn just inside edges that face down (transparent: none).
@export var shade_color: Color = Color(0.0, 0.0, 0.0, 0.0):
	set(value):
		shade_color = value
		_rebuild()
## Width of the lip and the shade, in pixels.
@export var lip_width: float = 10.0:
	set(value):
		lip_width = value
		_rebuild()
## Scale of the fill texture (2: texels twice as large).
@export var texture_scale: float = 1.0:
	set(value):
		texture_scale = value
		_rebuild()


func _ready() -> void:
	_rebuild()


func _rebuild() -> void:
	if not is_inside_tree():
		return
	for child: Node in get_children():
		if child.name.begins_with(_GENERATED_PREFIX):
			remove_child(child)
			child.queue_free()
	var outlines: Array[PackedVector2Array] = []
	for child: Node in get_children():
		var collider: CollisionPolygon2D = child as CollisionPolygon2D
		if collider != null and collider.polygon.size() >= 3:
			outlines.append(collider.transform * collider.polygon)
	outlines = _merged(outlines)
	for i: int in outlines.size():
		_draw_outline(outlines[i], i)


## Unites overlapping polygons so that no rim is drawn across the inside of the ground.
static func _merged(polygons: Array[PackedVector2Array]) -> Array[PackedVector2Array]:
	var result: Array[PackedVector2Array] = polygons.duplicate()
	var changed: bool = true
	while changed:
		changed = false
		for i: int in result.size():
			for j: int in range(i + 1, result.size()):
				var union: Array[PackedVector2Array] = Geometry2D.merge_polygons(
					result[i], result[j]
				)
				if union.size() == 1:
					result[i] = union[0]
					result.remove_at(j)
					changed = true
					break
			if changed:
				break
	return result


func _draw_outline(polygon: PackedVector2Array, index: int) -> void:
	var fill: Polygon2D = Polygon2D.new()
	fill.name = "%sFill%d" % [_GENERATED_PREFIX, index]
	fill.polygon = polygon
	fill.texture = fill_texture
	fill.texture_repeat = CanvasItem.TEXTURE_REPEAT_ENABLED
	fill.texture_scale = Vector2.ONE / maxf(texture_scale, 0.01)
	fill.color = fill_color
	add_child(fill)
	if highlight_color.a > 0.0:
		_draw_lips(polygon, index, -1.0, highlight_color, "Lip")
	if shade_color.a > 0.0:
		_draw_lips(polygon, index, 1.0, shade_color, "Shade")
	if edge_width <= 0.0:
		return
	var rim: Line2D = Line2D.new()
	rim.name = "%sRim%d" % [_GENERATED_PREFIX, index]
	rim.points = polygon
	rim.closed = true
	rim.width = edge_width
	rim.default_color = edge_color
	rim.joint_mode = Line2D.LINE_JOINT_ROUND
	add_child(rim)


## Draws a band just inside every run of edges whose outward normal's y has the sign of
## [param facing] (-1: edges facing up, floors; 1: facing down, ceilings).
func _draw_lips(
	polygon: PackedVector2Array, index: int, facing: float, color: Color, kind: String
) -> void:
	var count: int = polygon.size()
	# Outward normal of edge i (from point i to i + 1), whatever the winding.
	var clockwise: bool = Geometry2D.is_polygon_clockwise(polygon)
	var normals: PackedVector2Array = PackedVector2Array()
	normals.resize(count)
	for i: int in count:
		var edge: Vector2 = polygon[(i + 1) % count] - polygon[i]
		var n: Vector2 = Vector2(edge.y, -edge.x).normalized()
		normals[i] = -n if clockwise else n
	var qualifies: Callable = func(i: int) -> bool: return normals[i].y * facing > 0.35
	# Start the walk at an edge that does not qualify, so runs are not split at index 0.
	var start: int = -1
	for i: int in count:
		if not qualifies.call(i):
			start = i
			break
	if start < 0:
		return
	var run: PackedVector2Array = PackedVector2Array()
	var runs: int = 0
	for step: int in range(1, count + 1):
		var i: int = (start + step) % count
		if qualifies.call(i):
			var a: Vector2 = polygon[i]
			var b: Vector2 = polygon[(i + 1) % count]
			var inset: Vector2 = -normals[i] * lip_width * 0.5
			if run.is_empty():
				run.append(a + inset)
			else:
				run[run.size() - 1] = (run[run.size() - 1] + a + inset) * 0.5
			run.append(b + inset)
		elif not run.is_empty():
			_add_band("%s%s%d_%d" % [_GENERATED_PREFIX, kind, index, runs], run, color)
			runs += 1
			run = PackedVector2Array()
	if not run.is_empty():
		_add_band("%s%s%d_%d" % [_GENERATED_PREFIX, kind, index, runs], run, color)


func _add_band(band_name: String, points: PackedVector2Array, color: Color) -> void:
	var band: Line2D = Line2D.new()
	band.name = band_name
	band.points = points
	band.width = lip_width
	band.default_color = color
	band.joint_mode = Line2D.LINE_JOINT_ROUND
	band.begin_cap_mode = Line2D.LINE_CAP_ROUND
	band.end_cap_mode = Line2D.LINE_CAP_ROUND
	add_child(band)
