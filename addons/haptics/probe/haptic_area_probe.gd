@icon("res://addons/haptics/icons/haptic_probe.svg")
class_name HapticAreaProbe
extends Node
## Haptics for a player that is an [Area2D], such as the player of Godot's "Dodge the Creeps"
## tutorial: it moves by setting its position and learns of hits only as overlaps. Add this
## node as a child of the area. Every body or area that starts to overlap the player is a hit:
## an impact pushing the hand away from it, at the speed the two closed in on each other
## (each one's velocity: a rigid body's, a character's, else how far it moved by position: a
## node that began to overlap is watched until it is seen moving, or still, within the same
## frame). Both the player and what hits it may move in [code]_process[/code] or
## [code]_physics_process[/code], at any frame rate. Water (an area with
## [code]drag_coefficient[/code] and [code]inertia_force[/code], such as [HapticWater]) drags
## while the player is inside.
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
# How the player moves, and each overlapping node that moves by position (by instance id).
var _motion: Motion = null
var _others: Dictionary[int, Motion] = {}
# The nodes that began to overlap whose hit waits for their velocity (by instance id).
var _pending: Dictionary[int, bool] = {}
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
	_motion = Motion.new(_area)


func _process(delta: float) -> void:
	_look(delta, false)


func _physics_process(delta: float) -> void:
	_look(delta, true)
	var frame: HapticFrame = HapticFrame.new()
	var overlapping: Array[Node2D] = _area.get_overlapping_bodies()
	overlapping.append_array(_area.get_overlapping_areas())
	var still_there: Dictionary[int, bool] = {}
	for other: Node2D in overlapping:
		still_there[other.get_instance_id()] = true
		if &"drag_coefficient" in other and &"inertia_force" in other and not frame.in_water:
			frame.in_water = true
			frame.water_drag_n_s_per_m = other.get(&"drag_coefficient")
			frame.water_inertia_n = other.get(&"inertia_force")
	for id: int in _others.keys():
		if not still_there.has(id) and not _pending.has(id):
			_others.erase(id)
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
	return _motion.velocity() if _motion != null else Vector2.ZERO


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
	if other is RigidBody2D:
		_play(other, other.global_position, (other as RigidBody2D).linear_velocity)
	elif other is CharacterBody2D:
		_play(other, other.global_position, (other as CharacterBody2D).velocity)
	else:
		# Moved by position: how fast is known once it has been looked at again, later in
		# this same frame ([method _look]).
		var id: int = other.get_instance_id()
		_others[id] = Motion.new(other)
		_pending[id] = true


# Looks at how the player and the nodes moving by position moved in this phase of the main
# loop, and plays the hits that waited for a velocity now known (or for a node freed since:
# as if it stood still where it was last seen).
func _look(delta: float, in_physics: bool) -> void:
	_motion.look(delta, in_physics)
	for id: int in _others.keys():
		var motion: Motion = _others[id]
		var alive: bool = is_instance_valid(motion.node)
		if alive:
			motion.look(delta, in_physics)
		if _pending.has(id) and (not alive or motion.known()):
			_pending.erase(id)
			var other: Node2D = motion.node if alive else null
			_play(other, motion.last, motion.velocity() if alive else Vector2.ZERO)
		if not alive:
			_others.erase(id)


# The hit of [param other] (null once freed), at [param at] moving at [param velocity] px/s,
# as it starts to overlap the player.
func _play(other: Node2D, at: Vector2, velocity: Vector2) -> void:
	var away: Vector2 = _area.global_position - at
	if away.is_zero_approx():
		away = -velocity_px()
	var direction: Vector2 = away.normalized()
	var closing: float = (velocity - velocity_px()).dot(direction)
	var speed: float = closing / pixels_per_metre
	if speed < min_impact_speed or direction.is_zero_approx():
		return
	var material: HapticMaterial = HapticMaterial.of(other) if other != null else null
	if material == null and other is RigidBody2D:
		var physics: PhysicsMaterial = (other as RigidBody2D).physics_material_override
		material = HapticMaterial.from_physics_material(physics) if physics != null else null
	impact.emit(other, direction, speed)
	hit(direction, speed, material)


## How a node moves: how far it moved since last looked at, in each phase of the main loop,
## over that phase's time (frames for what moves in [code]_process[/code], ticks for what moves
## in [code]_physics_process[/code]), so a frame rate other than the tick rate does not change
## its velocity (at 144 fps and 60 ticks two or three frames' way lies between two ticks).
class Motion:
	extends RefCounted
	## The node watched.
	var node: Node2D = null
	## Where it was when last looked at.
	var last: Vector2 = Vector2.ZERO
	var _from_process: Vector2 = Vector2.ZERO
	var _from_physics: Vector2 = Vector2.ZERO
	var _moved: bool = false
	var _seen_in_process: bool = false
	var _seen_in_physics: bool = false

	func _init(p_node: Node2D) -> void:
		node = p_node
		last = p_node.global_position

	## Takes note of how far it moved in the phase now ending [param delta] seconds after
	## the same phase's last look.
	func look(delta: float, in_physics: bool) -> void:
		var here: Vector2 = node.global_position
		var velocity: Vector2 = (here - last) / maxf(delta, 1e-6)
		_moved = _moved or here != last
		last = here
		if in_physics:
			_from_physics = velocity
			_seen_in_physics = true
		else:
			_from_process = velocity
			_seen_in_process = true

	## Its velocity in px/s.
	func velocity() -> Vector2:
		return _from_process + _from_physics

	## Whether [method velocity] is known: seen moving, or still through both phases.
	func known() -> bool:
		return _moved or (_seen_in_process and _seen_in_physics)
