class_name CentreGauge
extends Control
## Shows where the handle is relative to where a trial starts: the workspace as a disc, the
## start zone as a ring, the handle as a dot, and how long it has been held there as an arc.

## The handle, normalised (game axes; the disc's edge is 1).
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


func _draw() -> void:
	var centre: Vector2 = size * 0.5
	var radius_px: float = minf(size.x, size.y) * 0.5 - 6.0
	var inside: bool = hand.distance_to(target) <= tolerance
	var accent: Color = Color(0.97, 0.51, 0.33)
	draw_circle(centre, radius_px, Color(0.09, 0.24, 0.37, 0.9))
	draw_arc(centre, radius_px, 0.0, TAU, 64, Color(0.33, 0.65, 0.83), 2.0, true)
	var zone: Vector2 = centre + target * radius_px
	var zone_radius: float = maxf(tolerance * radius_px, 6.0)
	draw_circle(zone, zone_radius, Color(0.4, 0.85, 0.55, 0.35 if inside else 0.18))
	draw_arc(zone, zone_radius, 0.0, TAU, 40, Color(0.4, 0.85, 0.55), 2.0, true)
	if progress > 0.0:
		draw_arc(zone, zone_radius + 6.0, -PI / 2.0, -PI / 2.0 + TAU * progress, 40, accent, 4.0)
	var dot: Vector2 = centre + hand.limit_length(1.1) * radius_px
	draw_circle(dot, 7.0, Color.WHITE if inside else accent)
