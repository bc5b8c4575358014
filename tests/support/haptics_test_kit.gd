class_name HapticsTestKit
extends RefCounted
## What tests need to drive the haptics through the same typed door games use: a door of the
## test's own (its own server, the simulated device open, outside the tree: no servo thread,
## no input feeding), stepped tick by tick, and terse makers of the values it takes.
## Free the door with the suite's [code]autofree()[/code]: its device closes with it.

const Door := preload("res://addons/haptics/door/haptics.gd")
const DT := 0.001


## A door with a server of its own and the simulated device open; its servo is stepped with
## [code]door.servo.step(dt)[/code] (or [method run]).
static func manual() -> Door:
	var door: Door = Door.new()
	door.device.open(door.device.get_simulated_id())
	return door


## Puts the simulated hand at [param target_m], metres, game axes (x right, y down).
static func set_hand_m(door: Door, target_m: Vector2) -> bool:
	return door.device.set_hand_target_3d(Vector3(target_m.x, -target_m.y, 0.0))


## Runs [param ticks] servo ticks of 1 ms, handing [param frame] over before each when given.
static func run(door: Door, ticks: int, frame: HapticFrame = null) -> bool:
	for i: int in ticks:
		if frame != null and not door.submit_frame(frame):
			return false
		if not door.servo.step(DT):
			return false
	return true


## A contact with [param normal] (game axes) and, when [param stiffness_n] is not negative,
## its own material.
static func contact(
	normal: Vector2, stiffness_n: float = -1.0, friction_n: float = 1.0
) -> HapticContact:
	var out: HapticContact = HapticContact.new()
	out.normal = normal
	if stiffness_n >= 0.0:
		out.material = HapticContactMaterial.new()
		out.material.stiffness_n = stiffness_n
		out.material.friction_n = friction_n
	return out


## A frame touching [param contacts].
static func frame_of(contacts: Array[HapticContact]) -> HapticFrame:
	var out: HapticFrame = HapticFrame.new()
	out.contacts = contacts
	return out


## A frame with one contact of [param normal] and its own material
## ([param stiffness_n], [param friction_n]; the servo's default when stiffness is negative).
static func wall(
	normal: Vector2, stiffness_n: float = -1.0, friction_n: float = 1.0
) -> HapticFrame:
	var contacts: Array[HapticContact] = [contact(normal, stiffness_n, friction_n)]
	return frame_of(contacts)


## A body of [param mass_kg] resting on the hand, pressing along [param normal].
static func load(normal: Vector2, mass_kg: float) -> HapticLoad:
	var out: HapticLoad = HapticLoad.new()
	out.normal = normal
	out.mass_kg = mass_kg
	return out


## An impact along [param direction] at [param speed_m_per_s], with the servo's default
## material unless [param gain_n_s_per_m] is not negative.
static func impact(
	direction: Vector2,
	speed_m_per_s: float,
	gain_n_s_per_m: float = -1.0,
	frequency_hz: float = 150.0,
	decay_s: float = 0.03
) -> HapticImpact:
	var out: HapticImpact = HapticImpact.new()
	out.direction = direction
	out.speed_m_per_s = speed_m_per_s
	if gain_n_s_per_m >= 0.0:
		out.material = HapticImpactMaterial.new()
		out.material.gain_n_s_per_m = gain_n_s_per_m
		out.material.frequency_hz = frequency_hz
		out.material.decay_s = decay_s
	return out


## The movement renderer's component [param part] (a [code]HapticMovementFacts.MovementForce[/code])
## of the door's last tick, newtons, game axes.
static func movement_part(door: Door, part: HapticMovementFacts.MovementForce) -> Vector2:
	return door.get_forces().parts[part]


## The device listed with [param id] by the door's enumeration, or [code]null[/code] when
## none is.
static func find_device(door: Door, id: String) -> HapticDeviceInfo:
	for device: HapticDeviceInfo in door.device.list_present():
		if device.id == id:
			return device
	return null


## Makes the door's force reach what it renders at once: no start-up ramp, no slew limit.
static func instant(door: Door) -> bool:
	var settings: HapticServoSettings = door.servo.get_settings()
	settings.safety.slew_rate_n_per_s = 0.0
	return door.servo.apply_settings(settings) and no_ramp(door)


## Makes the door render at full strength from its first tick (no start-up ramp).
static func no_ramp(door: Door) -> bool:
	var settings: HapticServoSettings = door.servo.get_settings()
	settings.safety.startup_ramp_s = 0.0
	return door.servo.apply_settings(settings)


## Makes the door's input vector the hand's position as it is (no dead zone).
static func no_dead_zone(door: Door) -> bool:
	var settings: HapticServoSettings = door.servo.get_settings()
	settings.input.dead_zone = 0.0
	return door.servo.apply_settings(settings)


## The door's movement renderer's settings.
static func movement(door: Door) -> HapticMovementSettings:
	return HapticsMovement.of(door).get_settings()


## A [HapticForces] from components named as the HUD names them: the movement renderer's
## ([code]HapticMovementFacts.MOVEMENT_FORCE_NAMES[/code]), [code]"impact"[/code] and
## [code]"total"[/code]; a component not given is zero.
static func forces_of(named: Dictionary[String, Vector2]) -> HapticForces:
	var out: HapticForces = HapticForces.new()
	for part: int in HapticMovementFacts.MOVEMENT_FORCE_NAMES.size():
		out.parts[part] = _named(named, HapticMovementFacts.MOVEMENT_FORCE_NAMES[part])
	out.impact = _named(named, "impact")
	out.total = _named(named, "total")
	return out


static func _named(named: Dictionary[String, Vector2], component: String) -> Vector2:
	return named[component] if named.has(component) else Vector2.ZERO
