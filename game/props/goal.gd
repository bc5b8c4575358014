class_name Goal
extends Area2D
## The end of a level: a beacon buoy whose lamp flashes; [signal reached] is emitted once
## when the player touches its light.

## Emitted once, the first time the player enters the goal.
signal reached

## Whether the player has reached the goal.
var is_reached: bool = false

var _time: float = 0.0

@onready var _lamp: Node2D = get_node_or_null(^"Lamp") as Node2D
@onready var _beam: Node2D = get_node_or_null(^"Beam") as Node2D
@onready var _burst: GPUParticles2D = get_node_or_null(^"Burst") as GPUParticles2D


func _ready() -> void:
	body_entered.connect(_on_body_entered)


func _process(delta: float) -> void:
	_time += delta
	var speed: float = 4.0 if is_reached else 1.2
	if _lamp != null:
		_lamp.modulate.a = 0.35 + 0.4 * absf(sin(_time * speed * 1.7))
	if _beam != null:
		_beam.rotation = sin(_time * speed * 0.6) * 0.9
	rotation = sin(_time * 1.1) * 0.04


func _on_body_entered(body: Node2D) -> void:
	if is_reached or not body is Player:
		return
	is_reached = true
	if _burst != null:
		_burst.restart()
	var effects: LevelEffects = get_tree().get_first_node_in_group(&"effects") as LevelEffects
	if effects != null:
		effects.play(&"goal", global_position, 1.0, 1.0)
	reached.emit()
