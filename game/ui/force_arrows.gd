class_name ForceArrows
extends Control
## Draws the rendered force as one arrow per component from a common origin, like the
## movement-based paper's figures 2 and 3: normal, friction, weight, drag, inertia, impact
## and their total, each in its own colour.
##
## Arrows are scaled so that the device's maximum force spans [member full_length]
## pixels; longer ones are capped at [member max_length_ratio] of that. Feed it with
## [method set_forces]; read back what is drawn with [method get_arrow].

## Colour of each force component.
const COLORS: Dictionary[String, Color] = {
	"normal": Color(0.31, 0.76, 0.97),
	"friction": Color(1.0, 0.72, 0.30),
	"weight": Color(0.75, 0.45, 0.95),
	"drag": Color(0.30, 0.86, 0.72),
	"inertia": Color(0.55, 0.60, 1.0),
	"impact": Color(1.0, 0.33, 0.36),
	"total": Color(1.0, 1.0, 1.0),
}
## Human-readable name of each component, for legends.
const LABELS: Dictionary[String, String] = {
	"normal": "Normal",
	"friction": "Friction",
	"weight": "Weight",
	"drag": "Water drag",
	"inertia": "Water inertia",
	"impact": "Impact",
	"total": "Total",
}
## Colour of the thin dark outline around every arrow.
const OUTLINE_COLOR: Color = Color(0.02, 0.06, 0.1, 0.8)
## Arrows shorter than this many pixels are not drawn.
const MIN_DRAWN_LENGTH: float = 2.0

## Length in pixels of an arrow of [member max_force] newtons.
@export var full_length: float = 70.0:
	set(value):
		full_length = maxf(value, 1.0)
		_recompute()
## Force that spans [member full_length] (the device's maximum force), in newtons.
@export var max_force: float = 3.3:
	set(value):
		max_force = maxf(value, 0.001)
		_recompute()
## Cap on the drawn length, as a multiple of [member full_length].
@export var max_length_ratio: float = 1.3
## Draw the small avatar glyph and the max-force ring at the origin.
@export var show_glyph: bool = true:
	set(value):
		show_glyph = value
		queue_redraw()
## Width of the component arrows; the total is drawn half again as wide.
@export var line_width: float = 4.0

var _forces: Dictionary[String, Vector2] = {}
var _arrows: Dictionary[String, Vector2] = {}
var _head: PackedVector2Array = PackedVector2Array([Vector2.ZERO, Vector2.ZERO, Vector2.ZERO])


func _init() -> void:
	mouse_filter = MOUSE_FILTER_IGNORE
	for component: String in COLORS:
		_forces[component] = Vector2.ZERO
		_arrows[component] = Vector2.ZERO


## Takes one tick's [HapticForces] (game axes, y down): the movement renderer's components,
## the impact and the total.
func set_forces(forces: HapticForces) -> void:
	_forces = components_of(forces)
	_recompute()


## The components drawn, by name: the movement renderer's (in its force enum's order), then
## the impact and the total.
static func components_of(forces: HapticForces) -> Dictionary[String, Vector2]:
	var out: Dictionary[String, Vector2] = {}
	for part: int in HapticMovementFacts.MOVEMENT_FORCE_NAMES.size():
		out[HapticMovementFacts.MOVEMENT_FORCE_NAMES[part]] = forces.parts[part]
	out["impact"] = forces.impact
	out["total"] = forces.total
	return out


## The arrow drawn for [param component]: a vector in pixels from the origin (y down),
## zero when the component is absent.
func get_arrow(component: String) -> Vector2:
	return _arrows.get(component, Vector2.ZERO)


## Pixels per newton currently used.
func get_pixels_per_newton() -> float:
	return full_length / max_force


func _recompute() -> void:
	var scale_px: float = get_pixels_per_newton()
	var cap: float = full_length * max_length_ratio
	for component: String in _forces:
		_arrows[component] = (_forces[component] * scale_px).limit_length(cap)
	queue_redraw()


func _draw() -> void:
	var origin: Vector2 = size * 0.5
	if show_glyph:
		_draw_glyph(origin)
	# Outlines first, so every arrow stays readable over bright scenery and over the others.
	for component: String in COLORS:
		_draw_arrow(origin, _arrows[component], OUTLINE_COLOR, _width(component), 2.0)
	for component: String in COLORS:
		_draw_arrow(origin, _arrows[component], COLORS[component], _width(component), 0.0)


func _draw_glyph(origin: Vector2) -> void:
	var ring: Color = Color(0.56, 0.70, 0.80, 0.28)
	draw_arc(origin, full_length, 0.0, TAU, 64, ring, 1.0, true)
	draw_arc(origin, full_length * 0.5, 0.0, TAU, 48, Color(ring, 0.14), 1.0, true)
	SubGlyph.draw(self, origin, 12.0, 0.8)


func _width(component: String) -> float:
	return line_width * 1.4 if component == "total" else line_width


func _draw_arrow(origin: Vector2, arrow: Vector2, color: Color, width: float, grow: float) -> void:
	var length: float = arrow.length()
	if length < MIN_DRAWN_LENGTH:
		return
	var direction: Vector2 = arrow / length
	var head_length: float = minf(width * 2.6, length * 0.6)
	var side: Vector2 = direction.orthogonal() * (width * 1.7 + grow)
	var tip: Vector2 = origin + arrow + direction * grow
	var base: Vector2 = origin + arrow - direction * (head_length + grow * 0.5)
	draw_line(origin - direction * grow * 0.5, base, color, width + grow * 2.0, true)
	_head[0] = tip
	_head[1] = base + side
	_head[2] = base - side
	draw_colored_polygon(_head, color)
