class_name HapticMaterial
extends Resource
## How a surface feels: contact stiffness and friction for the continuous force, and the
## shape of the transient played when something hits it.
##
## Assign it to a body by giving the body a [code]haptic_material[/code] property (scripted
## bodies such as crates) or a [code]haptic_material[/code] metadata entry (any body, set
## in the inspector). Bodies without one feel like the probe's default material.

## Normal-force gain k, in newtons per unit input: pushing the device to the edge of its
## workspace straight into the surface is resisted with this force.
@export_range(0.0, 100.0, 0.01, "suffix:N") var stiffness: float = 2.0
## Friction gain b, in newtons per unit input, against the input's tangential part.
@export_range(0.0, 100.0, 0.01, "suffix:N") var friction: float = 1.0
## Impact amplitude per metre per second of impact speed.
@export_range(0.0, 100.0, 0.01, "suffix:N·s/m") var impact_gain: float = 0.5
## Frequency of the impact transient.
@export_range(1.0, 1000.0, 1.0, "suffix:Hz") var impact_frequency: float = 150.0
## Decay time constant of the impact transient.
@export_range(0.001, 1.0, 0.001, "suffix:s") var impact_decay: float = 0.03
## The name [member friction] had before 0.3.0: materials saved with it still load (with a
## deprecation warning) until 0.4.0.
var damping: float:
	get:
		return friction
	set(value):
		push_warning("HapticMaterial.damping is deprecated: use friction (accepted until 0.4.0).")
		friction = value


## The material a body declares (property first, then metadata), or [code]null[/code].
static func of(body: Object) -> HapticMaterial:
	if body == null:
		return null
	var declared: Variant = body.get(&"haptic_material")
	if declared is HapticMaterial:
		return declared
	if body.has_meta(&"haptic_material"):
		var meta: Variant = body.get_meta(&"haptic_material")
		if meta is HapticMaterial:
			return meta
	return null
