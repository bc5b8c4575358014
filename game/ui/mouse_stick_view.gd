class_name MouseStickView
extends Control
## Draws the mouse stick while the player holds it (the left button held in the level): a
## ring where it was gripped, as wide as its full deflection, and a knob at the deflection.
## Nothing is drawn while it is let go, so a pointer left anywhere shows (and steers) nothing.

const RING_COLOUR := Color(1.0, 1.0, 1.0, 0.35)
const KNOB_COLOUR := Color(1.0, 0.6, 0.35, 0.85)
const KNOB_RADIUS := 12.0

var _stick: HapticsMouseStick = HapticsMouseStick.new()


func _ready() -> void:
	mouse_filter = MOUSE_FILTER_IGNORE
	set_anchors_preset(PRESET_FULL_RECT)


func _process(_delta: float) -> void:
	var stick: HapticsMouseStick = Haptics.get_mouse_stick()
	if stick.held or _stick.held:
		queue_redraw()
	_stick = stick


## The stick drawn now.
func get_stick() -> HapticsMouseStick:
	return _stick


func _draw() -> void:
	if not _stick.held:
		return
	var origin: Vector2 = _stick.origin - global_position
	var knob: Vector2 = origin + _stick.deflection() * _stick.radius
	draw_arc(origin, _stick.radius, 0.0, TAU, 64, RING_COLOUR, 2.0, true)
	draw_circle(origin, 3.0, RING_COLOUR)
	draw_line(origin, knob, RING_COLOUR, 2.0, true)
	draw_circle(knob, KNOB_RADIUS, KNOB_COLOUR)
