class_name StudyProbe
extends HapticProbe
## The maze study's [HapticProbe]: the movement-based renderer with each force switchable per
## condition (the study rendered the normal force only). Normal force, friction and impacts
## come from [member HapticProbe.default_material] (the study levels' walls declare no
## material of their own); the weight of resting objects and water drag/inertia are dropped
## from the frame unless enabled. With [member heartbeat_only] (position control, where the
## constraint renderer makes the force) it submits empty frames: the servo's watchdog and
## the frame clock of the 50 Hz proxy variant still tick.

## Keep resting objects (weight) in the frame.
var weight_enabled: bool = false
## Keep the water state (drag, inertia) in the frame.
var water_enabled: bool = false
## Submit empty frames (no contacts): position control.
var heartbeat_only: bool = false


## Sets the forces from a condition's settings ([method StudyConfig.condition]): keys
## [code]forces[/code] ({normal, friction, impact, weight, water: bool}),
## [code]stiffness[/code], [code]friction[/code] and [code]impact_gain[/code].
func configure(settings: Dictionary) -> void:
	var forces: Dictionary = settings.get("forces", {})
	var stiffness: float = settings.get("stiffness", 2.0)
	var friction: float = settings.get("friction", 1.0)
	var impact_gain: float = settings.get("impact_gain", 0.5)
	var material: HapticMaterial = HapticMaterial.new()
	material.stiffness = stiffness if _on(forces, "normal") else 0.0
	material.friction = friction if _on(forces, "friction") else 0.0
	material.impact_gain = impact_gain if _on(forces, "impact") else 0.0
	default_material = material
	weight_enabled = _on(forces, "weight")
	water_enabled = _on(forces, "water")


## The frame as [HapticProbe] builds it, with the disabled forces removed.
func build_frame() -> HapticFrame:
	if heartbeat_only:
		return HapticFrame.new()
	var frame: HapticFrame = super()
	if not weight_enabled:
		frame.resting.clear()
	if not water_enabled:
		frame.in_water = false
	return frame


static func _on(forces: Dictionary, force: String) -> bool:
	var enabled: bool = forces.get(force, false)
	return enabled
