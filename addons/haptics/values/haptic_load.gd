class_name HapticLoad
extends RefCounted
## A body resting on the hand in a [HapticFrame]: the direction its weight presses (unit,
## game axes) and its mass.

var normal: Vector2 = Vector2.ZERO
var mass_kg: float = 0.0


func _init(p_normal: Vector2 = Vector2.ZERO, p_mass_kg: float = 0.0) -> void:
	normal = p_normal
	mass_kg = p_mass_kg


## The entry of a frame's [code]resting[/code] (layout: HapticsServer.submit_frame).
func to_dictionary() -> Dictionary:
	return {"normal": normal, "mass_kg": mass_kg}
