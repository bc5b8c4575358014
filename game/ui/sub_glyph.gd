class_name SubGlyph
extends RefCounted
## Draws the avatar's silhouette, a small submarine facing right, on any [CanvasItem]:
## the menu backdrop and the HUD's force diagram use it.

## Hull colour (the avatar's orange).
const HULL_COLOR: Color = Color(0.97, 0.51, 0.33)
## Porthole colour.
const WINDOW_COLOR: Color = Color(0.62, 0.89, 0.98)
## Darker trim (tower, fins, propeller).
const TRIM_COLOR: Color = Color(0.80, 0.36, 0.22)

static var _hull: PackedVector2Array = _ellipse(Vector2.ZERO, Vector2(1.0, 0.52), 20)
static var _tower: PackedVector2Array = PackedVector2Array(
	[Vector2(-0.28, -0.44), Vector2(-0.20, -0.80), Vector2(0.22, -0.80), Vector2(0.32, -0.44)]
)
static var _fin: PackedVector2Array = PackedVector2Array(
	[
		Vector2(-0.86, -0.18),
		Vector2(-1.22, -0.52),
		Vector2(-1.12, 0.0),
		Vector2(-1.22, 0.52),
		Vector2(-0.86, 0.18)
	]
)


## Draws the submarine centred at [param at], [param half_length] pixels from centre to
## nose, with opacity [param alpha].
static func draw(canvas: CanvasItem, at: Vector2, half_length: float, alpha: float = 1.0) -> void:
	var transform: Transform2D = Transform2D(0.0, Vector2.ONE * half_length, 0.0, at)
	canvas.draw_set_transform_matrix(transform)
	canvas.draw_colored_polygon(_fin, Color(TRIM_COLOR, alpha))
	canvas.draw_colored_polygon(_tower, Color(TRIM_COLOR, alpha))
	canvas.draw_line(Vector2(0.05, -0.8), Vector2(0.05, -1.0), Color(TRIM_COLOR, alpha), 0.08)
	canvas.draw_line(Vector2(0.05, -1.0), Vector2(0.25, -1.0), Color(TRIM_COLOR, alpha), 0.08)
	canvas.draw_colored_polygon(_hull, Color(HULL_COLOR, alpha))
	canvas.draw_circle(Vector2(0.42, -0.05), 0.2, Color(WINDOW_COLOR, alpha))
	canvas.draw_circle(Vector2(-0.05, -0.05), 0.13, Color(WINDOW_COLOR, alpha * 0.8))
	canvas.draw_set_transform_matrix(Transform2D.IDENTITY)


static func _ellipse(centre: Vector2, radii: Vector2, segments: int) -> PackedVector2Array:
	var points: PackedVector2Array = PackedVector2Array()
	for i: int in segments:
		var angle: float = TAU * float(i) / float(segments)
		points.append(centre + Vector2(cos(angle) * radii.x, sin(angle) * radii.y))
	return points
