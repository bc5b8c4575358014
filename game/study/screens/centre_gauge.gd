class_name CentreGauge
extends Control
## Shows where the handle is relative to where a trial starts, as a close-up of the start:
## the disc spans [constant VIEW_ZONES] zone radii around the start zone, so the zone is
## drawn as wide as it is tested at any tolerance, the handle's dot is inside the ring
## exactly when the test counts it inside, and a handle further away sits on the disc's
## edge in its direction. How long it has been held there shows as an arc.

## How many zone radii the disc's radius stands for.
const VIEW_ZONES: float = 4.0
const DOT_RADIUS: float = 3.0

## The handle, normalised (game axes; 1 is the workspace's edge).
var hand: Vector2 = Vector2.ZERO:
	set(value):
		hand = value
		queue_redraw()
## Centre of the start zone, normalised.
var target: Vector2 = Vector2.ZERO:
	set(value):
		target = value
		queue_redraw()
## Radius of the start zone, normalised.
var tolerance: float = 0.05:
	set(value):
		tolerance = value
		queue_redraw()
## 0–1: how much of the required hold time has passed.
var progress: float = 0.0:
	set(value):
		progress = clampf(value, 0.0, 1.0)
		queue_redraw()


## Whether the handle counts as in the start zone (what the trial's start tests).
func is_inside() -> bool:
	return hand.distance_to(target) <= tolerance


## The radius of the start zone as drawn, pixels.
func zone_radius() -> float:
	return _disc_radius() / VIEW_ZONES


## Where the handle's dot is drawn, in this control's pixels.
func dot_position() -> Vector2:
	var offset: Vector2 = (hand - target) / tolerance * zone_radius()
	return size * 0.5 + offset.limit_length(_disc_radius())


func _disc_radius() -> float:
	return minf(size.x, size.y) * 0.5 - 6.0


func _draw() -> void:
	var centre: Vector2 = size * 0.5
	var radius_px: float = _disc_radius()
	var inside: bool = is_inside()
	var accent: Color = Color(0.97, 0.51, 0.33)
	draw_circle(centre, radius_px, Color(0.09, 0.24, 0.37, 0.9))
	draw_arc(centre, radius_px, 0.0, TAU, 64, Color(0.33, 0.65, 0.83), 2.0, true)
	var zone: float = zone_radius()
	draw_circle(centre, zone, Color(0.4, 0.85, 0.55, 0.35 if inside else 0.18))
	draw_arc(centre, zone, 0.0, TAU, 40, Color(0.4, 0.85, 0.55), 2.0, true)
	if progress > 0.0:
		draw_arc(centre, zone + 6.0, -PI / 2.0, -PI / 2.0 + TAU * progress, 40, accent, 4.0)
	draw_circle(dot_position(), DOT_RADIUS, Color.WHITE if inside else accent)
