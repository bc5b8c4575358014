class_name TestRoom
extends Node2D
## A closed room with a slanted block: the smallest real level, used by the foundation
## tests and by [code]make play[/code] until the full level exists.

## Emitted when the player bumps into anything, with the impact speed in pixels/second.
signal player_bumped(normal: Vector2, speed: float)

@onready var player: Player = $Player


func _ready() -> void:
	player.bumped.connect(_on_player_bumped)


func _on_player_bumped(_collider: Object, p_normal: Vector2, p_speed: float) -> void:
	player_bumped.emit(p_normal, p_speed)
