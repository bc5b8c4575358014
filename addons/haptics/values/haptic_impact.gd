class_name HapticImpact
extends RefCounted
## A contact that began, for the servo's impact transient: the direction (unit, game axes,
## from the surface toward the body), the approach speed, and the [HapticMaterial] whose
## impact gain, frequency and decay shape the ring (null: the server's default material).

var direction: Vector2 = Vector2.ZERO
var speed_m_per_s: float = 0.0
var material: HapticMaterial = null


func _init(
	p_direction: Vector2 = Vector2.ZERO,
	p_speed_m_per_s: float = 0.0,
	p_material: HapticMaterial = null
) -> void:
	direction = p_direction
	speed_m_per_s = p_speed_m_per_s
	material = p_material


## The dictionary [code]HapticsServer.push_impact[/code] takes.
func to_dictionary() -> Dictionary:
	var out: Dictionary = {"direction": direction, "speed_m_per_s": speed_m_per_s}
	if material != null:
		out["gain_n_s_per_m"] = material.impact_gain
		out["frequency_hz"] = material.impact_frequency
		out["decay_s"] = material.impact_decay
	return out
