@icon("res://addons/haptics/icons/haptic_probe.svg")
class_name HapticAreaProbe
extends Node
## Haptics for a player that is an [Area2D], such as the player of Godot's "Dodge the Creeps"
## tutorial: it moves by setting its position and learns of hits only as overlaps. Add this
## node as a child of the area. Every body or area that starts to overlap the player is a hit:
## an impact pushing the hand away from it, at the speed the two closed in on each other
## (each one's velocity: a rigid body's, a character's, else how far it moved since the last
## physics tick). Water (an area with [code]drag_coefficient[/code] and
## [code]inertia_force[/code], such as [HapticWater]) drags while the player is inside.
## [br][br]
## An area does not stop at what it touches, so there is no lasting push, only the hit; a
## player that is a [CharacterBody2D] or [RigidBody2D] takes a [HapticProbe] instead.

## Emitted for each hit played, with the speed in metres per second.
signal impact(collider: Object, direction: Vector2, speed: float)

const Haptics := preload("res://addons/haptics/door/haptics.gd")
## The probe's process and physics priority: after the game's nodes (default 0).
const AFTER_THE_GAME := 1000

## World scale: pixels per metre (see [member HapticProbe.pixels_per_metre]).
@export_range(1.0, 10000.0, 0.1, "suffix:px/m") var pixels_per_metre: float = 100.0
## How a hit rings for a collider that declares no [HapticMaterial]; null: the servo's default.
@export var default_material: HapticMaterial = null
## Hits slower than this are not played, in metres per second.
@export_range(0.0, 10.0, 0.01, "suffix:m/s") var min_impact_speed: float = 0.2

## The door hits and frames go to: the [code]Haptics[/code] autoload unless set before the
## probe enters the tree.
var haptics: Haptics = null
## The last frame submitted (no contacts: the player's velocity and the water it is in).
var last_frame: HapticFrame = HapticFrame.new()

var _area: Area2D = null
# Where the player was when last seen (in either callback), and each overlapping node at the
# last physics tick, for the velocity of what moves by position.
var _last_position: Vector2 = Vector2.ZERO
var _seen_at: Dictionary[int, Vector2] = {}
# The player's velocity in px/s, from how far it moved in each phase of the main loop, each
# against its own phase's time: a player moved in _process (the tutorial's) moves between
# frames, one moved in _physics_process between ticks, and a frame rate other than the tick
# rate puts two or three frames' movement (at 144 fps and 60 ticks) between two ticks.
var _velocity_from_process: Vector2 = Vector2.ZERO
var _velocity_from_physics: Vector2 = Vector2.ZERO
var _sequence: int = 0


func _ready() -> void:
	_area = get_parent() as Area2D
	if _area == null:
		push_error(
			"HapticAreaProbe must be a child of an Area2D (a body player takes a HapticProbe)."
		)
		set_process(false)
		set_physics_process(false)
		return
	if haptics == null:
		haptics = get_node_or_null(^"/root/Haptics") as Haptics
	if haptics == null:
		push_error("HapticAreaProbe: no Haptics autoload; enable the Haptics plugin.")
		set_process(false)
		set_physics_process(false)
		return
	# After the game's own nodes in both phases: what moved the player this frame or tick
	# has moved it when this probe looks.
	process_priority = AFTER_THE_GAME
	process_physics_priority = AFTER_THE_GAME
	_area.monitoring = true
	_area.body_entered.connect(_on_entered)
	_area.area_entered.connect(_on_entered)
	_last_position = _area.global_position


func _process(delta: float) -> void:
	_velocity_from_process = _moved() / maxf(delta, 1e-6)


func _physics_process(delta: float) -> void:
	_velocity_from_physics = _moved() / maxf(delta, 1e-6)
	var frame: HapticFrame = HapticFrame.new()
	for other: Node2D in _area.get_overlapping_bodies() + _area.get_overlapping_areas():
		_seen_at[other.get_instance_id()] = other.global_position
		if &"drag_coefficient" in other and &"inertia_force" in other and not frame.in_water:
			frame.in_water = true
			frame.water_drag_n_s_per_m = other.get(&"drag_coefficient")
			frame.water_inertia_n = other.get(&"inertia_force")
	frame.velocity_m_per_s = velocity_px() / pixels_per_metre
	_sequence += 1
	frame.sequence = _sequence
	frame.time_s = Time.get_ticks_msec() / 1000.0
	haptics.submit_frame(frame)
	last_frame = frame


## The player's velocity in pixels per second: how far it moved since it was last seen, over
## the time of the phase it moved in (between frames for a player moved in
## [code]_process[/code], between physics ticks for one moved in
## [code]_physics_process[/code]), so a frame rate other than the tick rate does not change it.
func velocity_px() -> Vector2:
	return _velocity_from_process + _velocity_from_physics


## Plays a hit on the hand: a push along [param p_direction] (from what hit toward the
## player) at [param p_speed_m_per_s], ringing like [param p_material] (null: the probe's
## default). The one line a kill zone or an enemy's handler needs, e.g.
## [code]$Player/HapticAreaProbe.hit(Vector2.UP, 3.0)[/code].
func hit(p_direction: Vector2, p_speed_m_per_s: float, p_material: HapticMaterial = null) -> void:
	var material: HapticMaterial = p_material if p_material != null else default_material
	HapticProbe.play_hit(haptics, p_direction, p_speed_m_per_s, material)


func _on_entered(other: Node2D) -> void:
	if &"drag_coefficient" in other and &"inertia_force" in other:
		return  # Water is felt as drag, not as a hit.
	var away: Vector2 = _area.global_position - other.global_position
	if away.is_zero_approx():
		away = -velocity_px()
	var direction: Vector2 = away.normalized()
	var closing: float = (_velocity_of(other) - velocity_px()).dot(direction)
	var speed: float = closing / pixels_per_metre
	if speed < min_impact_speed or direction.is_zero_approx():
		return
	var material: HapticMaterial = HapticMaterial.of(other)
	if material == null and other is RigidBody2D:
		var physics: PhysicsMaterial = (other as RigidBody2D).physics_material_override
		material = HapticMaterial.from_physics_material(physics) if physics != null else null
	impact.emit(other, direction, speed)
	hit(direction, speed, material)


# A node's velocity in pixels per second: a rigid body's or a character's own, else how far
# it moved since the last physics tick this probe saw it (0 the first time).
func _velocity_of(other: Node2D) -> Vector2:
	if other is RigidBody2D:
		return (other as RigidBody2D).linear_velocity
	if other is CharacterBody2D:
		return (other as CharacterBody2D).velocity
	var id: int = other.get_instance_id()
	var before: Vector2 = _seen_at.get(id, other.global_position)
	return (other.global_position - before) * Engine.physics_ticks_per_second


# How far the player moved since this probe last looked (in either callback).
func _moved() -> Vector2:
	var here: Vector2 = _area.global_position
	var moved: Vector2 = here - _last_position
	_last_position = here
	return moved
