class_name HapticContact
extends RefCounted
## One surface the body touches in a [HapticFrame]: the contact normal (unit, from the
## surface toward the body, game axes) and the surface's [HapticMaterial] (null: the
## server's default material).

var normal: Vector2 = Vector2.ZERO
var material: HapticMaterial = null


func _init(p_normal: Vector2 = Vector2.ZERO, p_material: HapticMaterial = null) -> void:
	normal = p_normal
	material = p_material


## The entry of a frame's [code]contacts[/code] (layout: HapticsServer.submit_frame).
func to_dictionary() -> Dictionary:
	var out: Dictionary = {"normal": normal}
	if material != null:
		out["stiffness_n"] = material.stiffness
		out["friction_n"] = material.friction
	return out
