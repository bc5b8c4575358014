@tool
class_name StudyGoal
extends Area2D
## The goal of a study level: a pad the avatar drives onto. [signal reached] is emitted once
## when a [Player] body enters it (also a follower body moved by the constraint renderer);
## [method reset] arms it again (practice runs).

## Emitted the first time the player enters the goal after [method reset].
signal reached

## Radius of the drawn pad, pixels (the collision shape is set separately).
@export var radius: float = 34.0:
	set(value):
		radius = value
		queue_redraw()
@export var color: Color = Color(0.99, 0.62, 0.3):
	set(value):
		color = value
		queue_redraw()

## Whether the goal has been reached since the last [method reset].
var is_reached: bool = false

var _time: float = 0.0


func _ready() -> void:
	collision_layer = 0
	collision_mask = 2
	monitorable = false
	if not Engine.is_editor_hint():
		body_entered.connect(_on_body_entered)


func _process(delta: float) -> void:
	if Engine.is_editor_hint():
		return
	_time += delta
	queue_redraw()


## Arms the goal again.
func reset() -> void:
	is_reached = false


func _draw() -> void:
	var pulse: float = 0.5 + 0.5 * sin(_time * 3.0)
	draw_circle(Vector2.ZERO, radius, Color(color, 0.18 + 0.12 * pulse))
	draw_arc(Vector2.ZERO, radius, 0.0, TAU, 48, color, 3.0, true)
	draw_arc(Vector2.ZERO, radius * 0.55, 0.0, TAU, 32, Color(color, 0.8), 2.0, true)
	# A small flag on a pole.
	var pole: Vector2 = Vector2(-4.0, 12.0)
	draw_line(pole, pole + Vector2(0.0, -34.0), Color(0.95, 0.95, 0.95), 3.0, true)
	var flag: PackedVector2Array = [
		pole + Vector2(0.0, -34.0), pole + Vector2(22.0, -27.0), pole + Vector2(0.0, -20.0)
	]
	draw_colored_polygon(flag, color)


func _on_body_entered(body: Node2D) -> void:
	if is_reached or not body is Player:
		return
	is_reached = true
	reached.emit()
