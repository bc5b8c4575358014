class_name Pearl
extends Area2D
## A collectible pearl in an open clam: glows, and is picked up when the player touches it.

## Emitted once, when the player picks the pearl up.
signal collected(pearl: Pearl)

## Whether the pearl has been picked up.
var is_collected: bool = false

var _time: float = 0.0

@onready var _glow: Node2D = get_node_or_null(^"Glow") as Node2D
@onready var _pearl: Node2D = get_node_or_null(^"Pearl") as Node2D


func _ready() -> void:
	body_entered.connect(_on_body_entered)
	_time = fposmod(global_position.x * 0.013, TAU)


func _process(delta: float) -> void:
	_time += delta
	if _glow != null:
		var pulse: float = 0.5 + 0.5 * sin(_time * 3.0)
		_glow.modulate.a = 0.45 + 0.4 * pulse
		_glow.scale = Vector2.ONE * (0.9 + 0.2 * pulse)
	if _pearl != null and not is_collected:
		_pearl.position.y = -10.0 + sin(_time * 2.0) * 1.5


func _on_body_entered(body: Node2D) -> void:
	if is_collected or not body is Player:
		return
	is_collected = true
	set_deferred(&"monitoring", false)
	collected.emit(self)
	var effects: LevelEffects = get_tree().get_first_node_in_group(&"effects") as LevelEffects
	if effects != null:
		effects.play(&"pearl", global_position, 0.8, 1.0)
	var tween: Tween = create_tween().set_parallel()
	if _pearl != null:
		tween.tween_property(_pearl, ^"position:y", -70.0, 0.5).set_ease(Tween.EASE_OUT)
		tween.tween_property(_pearl, ^"scale", Vector2.ONE * 1.8, 0.5)
		tween.tween_property(_pearl, ^"modulate:a", 0.0, 0.5)
	if _glow != null:
		tween.tween_property(_glow, ^"scale", Vector2.ONE * 3.0, 0.5)
	tween.chain().tween_callback(_hide_pearl)


func _hide_pearl() -> void:
	if _pearl != null:
		_pearl.visible = false
	if _glow != null:
		_glow.visible = false
