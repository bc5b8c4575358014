class_name MenuBackground
extends Control
## The menus' animated backdrop: a deep-water gradient, slanted light shafts, rising
## bubbles, a drifting submarine and a rocky seabed, all drawn procedurally.

## Colour at the top of the gradient.
@export var top_color: Color = Color(0.09, 0.28, 0.42)
## Colour at the bottom of the gradient.
@export var bottom_color: Color = Color(0.02, 0.06, 0.12)
@export var bubble_count: int = 36

var _time: float = 0.0
var _bubbles: PackedVector3Array = PackedVector3Array()
var _seabed: PackedVector2Array = PackedVector2Array()
var _gradient: PackedVector2Array = PackedVector2Array()
var _gradient_colors: PackedColorArray = PackedColorArray()


func _init() -> void:
	mouse_filter = MOUSE_FILTER_IGNORE
	var rng: RandomNumberGenerator = RandomNumberGenerator.new()
	rng.seed = 7
	for i: int in bubble_count:
		# x fraction, phase, radius
		_bubbles.append(Vector3(rng.randf(), rng.randf(), rng.randf_range(2.0, 6.0)))
	_gradient.resize(4)
	_gradient_colors = PackedColorArray([top_color, top_color, bottom_color, bottom_color])


func _process(delta: float) -> void:
	_time += delta
	queue_redraw()


func _notification(what: int) -> void:
	if what == NOTIFICATION_RESIZED:
		_build_seabed()
	elif what == NOTIFICATION_VISIBILITY_CHANGED:
		# Hidden (a headless server, a screen over it), it would still redraw every frame.
		set_process(is_visible_in_tree())


func _build_seabed() -> void:
	_seabed.clear()
	var width: float = size.x
	var height: float = size.y
	var rng: RandomNumberGenerator = RandomNumberGenerator.new()
	rng.seed = 11
	_seabed.append(Vector2(0.0, height))
	var x: float = 0.0
	while x < width + 80.0:
		_seabed.append(Vector2(x, height - 70.0 - rng.randf_range(0.0, 60.0)))
		x += rng.randf_range(50.0, 110.0)
	_seabed.append(Vector2(x, height))


func _draw() -> void:
	var width: float = size.x
	var height: float = size.y
	_gradient[0] = Vector2(0.0, 0.0)
	_gradient[1] = Vector2(width, 0.0)
	_gradient[2] = Vector2(width, height)
	_gradient[3] = Vector2(0.0, height)
	draw_polygon(_gradient, _gradient_colors)
	for i: int in 5:
		var x0: float = width * (0.12 + 0.2 * float(i)) + sin(_time * 0.2 + float(i)) * 30.0
		var shaft: PackedVector2Array = PackedVector2Array(
			[
				Vector2(x0, 0.0),
				Vector2(x0 + 70.0, 0.0),
				Vector2(x0 - 140.0, height),
				Vector2(x0 - 260.0, height),
			]
		)
		draw_colored_polygon(shaft, Color(0.6, 0.85, 1.0, 0.035))
	for bubble: Vector3 in _bubbles:
		var rise: float = fmod(bubble.y + _time * (0.03 + bubble.z * 0.006), 1.0)
		var bx: float = bubble.x * width + sin(_time * 1.3 + bubble.y * 20.0) * 6.0
		var by: float = height * (1.0 - rise)
		draw_arc(Vector2(bx, by), bubble.z, 0.0, TAU, 16, Color(0.75, 0.92, 1.0, 0.35), 1.2)
	_draw_submarine(
		Vector2(fmod(_time * 40.0, width + 300.0) - 150.0, height * 0.62 + sin(_time) * 10.0)
	)
	if _seabed.size() > 2:
		draw_colored_polygon(_seabed, Color(0.03, 0.1, 0.14))


func _draw_submarine(at: Vector2) -> void:
	SubGlyph.draw(self, at, 46.0, 0.5)
