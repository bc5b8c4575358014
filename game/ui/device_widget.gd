class_name DeviceWidget
extends Control
## The simulated device's workspace seen from the front: a circle of radius 1 (the
## normalised workspace), the hand target as a ring and the device position as a filled
## dot, joined by the spring the simulated hand pulls with.

## Colour of the device position's dot.
@export var device_color: Color = Color(0.97, 0.51, 0.33)
## Colour of the hand target ring.
@export var hand_color: Color = Color(1.0, 1.0, 1.0)
## Colour of the workspace outline and crosshair.
@export var frame_color: Color = Color(0.56, 0.70, 0.80, 0.45)

## Device position, normalised to the workspace (each axis in [-1, 1], y down).
var device_position: Vector2 = Vector2.ZERO
## Hand target, normalised to the workspace.
var hand: Vector2 = Vector2.ZERO


func _init() -> void:
	mouse_filter = MOUSE_FILTER_IGNORE


## Sets both positions (normalised, game axes) and redraws when they moved.
func set_positions(p_device_position: Vector2, p_hand: Vector2) -> void:
	if p_device_position.is_equal_approx(device_position) and p_hand.is_equal_approx(hand):
		return
	device_position = p_device_position
	hand = p_hand
	queue_redraw()


## Where a normalised position is drawn, in local pixels.
func to_local_point(normalized: Vector2) -> Vector2:
	return size * 0.5 + normalized.limit_length(1.2) * _radius()


func _radius() -> float:
	return maxf(minf(size.x, size.y) * 0.5 - 8.0, 4.0)


func _draw() -> void:
	var centre: Vector2 = size * 0.5
	var radius: float = _radius()
	draw_circle(centre, radius, Color(0.02, 0.07, 0.12, 0.6))
	draw_arc(centre, radius, 0.0, TAU, 48, frame_color, 1.5, true)
	draw_line(centre - Vector2(radius, 0), centre + Vector2(radius, 0), Color(frame_color, 0.2))
	draw_line(centre - Vector2(0, radius), centre + Vector2(0, radius), Color(frame_color, 0.2))
	var device_at: Vector2 = to_local_point(device_position)
	var hand_at: Vector2 = to_local_point(hand)
	draw_line(device_at, hand_at, Color(hand_color, 0.45), 1.5, true)
	draw_arc(hand_at, 6.0, 0.0, TAU, 24, hand_color, 2.0, true)
	draw_circle(device_at, 5.0, device_color)
