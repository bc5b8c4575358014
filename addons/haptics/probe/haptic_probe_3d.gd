@icon("res://addons/haptics/icons/haptic_probe.svg")
class_name HapticProbe3D
extends Node
## Drop-in haptics for any 3D body: add this node as a child of a [CharacterBody3D] or
## [RigidBody3D] and the body's contacts are felt, as [HapticProbe] does in 2D.
##
## At every physics tick it gathers the body's contacts, one per touched shape or [GridMap]
## cell (normals and each one's [HapticMaterial]), dynamic bodies resting on top of it (mass
## and normal), the water volume it is in ([HapticWater3D]), its velocity, and the speed of
## new touches, and submits them to the servo as a [HapticFrame3D]. Godot's 3D units are
## metres: no scale to set.
## [br][br]
## Vectors reach the device as the player sees them: turned into the [member view]'s facing
## (the viewport's camera unless set; its heading only), so a wall in front of the camera
## pushes the stylus back toward the player whatever way the world faces. A 3-DOF device
## (Touch, Falcon, the simulated one) feels all three axes; a 2-axis stick the ground plane,
## forward being into the screen (docs/probe-3d.md).
## [br][br]
## With [member drive_input] the device's input vector is handed to the body's
## [code]input_vector[/code] property (a [Vector3] in world space, turned back from the view)
## before the body moves: pushing the stylus forward means "away from the camera".

## Emitted after each frame is submitted, with the frame as sent.
signal frame_submitted(frame: HapticFrame3D)
## Emitted when a new touch begins, with the approach speed in metres per second (normal in
## world space).
signal impact(collider: Object, normal: Vector3, speed: float)

## Contact normals of one collider closer than this (cosine) are one face.
const SAME_FACE_COS := 0.999
const Haptics := preload("res://addons/haptics/door/haptics.gd")
const HapticsLookup := preload("res://addons/haptics/door/haptics_lookup.gd")
const HapticBodyContacts3D := preload("res://addons/haptics/probe/haptic_body_contacts_3d.gd")
const HapticTouches := preload("res://addons/haptics/probe/haptic_touches.gd")

## The node whose heading the device follows (a camera, or the player's pivot); null: the
## viewport's current [Camera3D] each tick, else the world's own axes.
@export var view: Node3D = null
## Material for bodies that declare none; [code]null[/code] uses the servo's default.
@export var default_material: HapticMaterial = null
## Feed the device's input vector to the body's [code]input_vector[/code] property when
## the control mode is "device".
@export var drive_input: bool = true
## How far above the body to look for objects resting on it, in metres.
@export_range(0.001, 0.5, 0.001, "suffix:m") var resting_probe_distance: float = 0.02
## While standing on a floor, the avatar's own weight presses the hand down with this mass ×
## the movement renderer's [member HapticForceModelSettings.gravity_n_per_kg]; 0 (the
## default) leaves standing still force-free.
@export_range(0.0, 10.0, 0.01, "suffix:kg") var own_weight_kg: float = 0.0
## Impacts slower than this are not played, in metres per second.
@export_range(0.0, 10.0, 0.01, "suffix:m/s") var min_impact_speed: float = 0.2
## A shape lost for less than this and touched again is the same touch, not a new impact.
@export_range(0.0, 1.0, 0.01, "suffix:s") var touch_release_s: float = 0.1

## The door this probe hands its frames and impacts to: the [code]Haptics[/code] autoload
## unless set before the probe enters the tree.
var haptics: Haptics = null
## The last frame submitted (for HUDs and tests).
var last_frame: HapticFrame3D = HapticFrame3D.new()
## Frames submitted so far.
var frames_submitted: int = 0

var _body: PhysicsBody3D = null
var _contacts: HapticBodyContacts3D = null
var _touches: HapticTouches = HapticTouches.new()
var _sequence: int = 0
var _velocity_before: Vector3 = Vector3.ZERO
var _query: PhysicsPointQueryParameters3D = PhysicsPointQueryParameters3D.new()


func _ready() -> void:
	_body = get_parent() as PhysicsBody3D
	if _body == null:
		push_error("HapticProbe3D must be a child of a CharacterBody3D or RigidBody3D.")
		set_physics_process(false)
		return
	if haptics == null:
		haptics = HapticsLookup.autoload_for(self, "HapticProbe3D")
	if haptics == null:
		set_physics_process(false)
		return
	if _body is RigidBody3D:
		var rigid: RigidBody3D = _body
		rigid.contact_monitor = true
		rigid.max_contacts_reported = maxi(rigid.max_contacts_reported, 8)
	_contacts = HapticBodyContacts3D.new(_body)
	if _contacts.solid_shapes().is_empty():
		push_warning(
			(
				"HapticProbe3D: no solid collision shape on %s; objects resting on it are not felt."
				% _body.name
			)
		)
	_query.collide_with_areas = true
	_query.collide_with_bodies = false
	get_tree().physics_frame.connect(_before_bodies_move)


func _exit_tree() -> void:
	if get_tree().physics_frame.is_connected(_before_bodies_move):
		get_tree().physics_frame.disconnect(_before_bodies_move)


# Before any node's _physics_process: the body reads this tick's input vector, and a
# character's velocity as it arrives is what new contacts are hit at.
func _before_bodies_move() -> void:
	if _body is CharacterBody3D:
		_velocity_before = (_body as CharacterBody3D).velocity
	if not drive_input or not (&"input_vector" in _body):
		return
	var device_driven: bool = (
		haptics.control_mode == Haptics.CONTROL_DEVICE and not haptics.device.is_lost()
	)
	if &"use_keyboard" in _body:
		_body.set(&"use_keyboard", not device_driven)
	if device_driven:
		_body.set(&"input_vector", view_basis() * haptics.get_input_vector_3d())


func _physics_process(_delta: float) -> void:
	submit()


## Gathers this tick's frame and hands it to the door, pushing impacts for touches that began.
func submit() -> void:
	var frame: HapticFrame3D = build_frame()
	haptics.submit_frame_3d(frame)
	last_frame = frame
	frames_submitted += 1
	frame_submitted.emit(frame)


## The view's heading as a basis ([method heading] of [member view], else of the viewport's
## camera): world vectors reach the device as [code]basis.transposed() * v[/code].
func view_basis() -> Basis:
	return heading(view if view != null else get_viewport().get_camera_3d())


## [param node]'s heading as a basis: columns right, up and back (toward the player), level
## with the ground whatever its pitch and roll; the world's own axes for null.
static func heading(node: Node3D) -> Basis:
	if node == null:
		return Basis.IDENTITY
	var back: Vector3 = node.global_basis.z
	# Looking straight down, the node's top edge is its forward.
	back = back if absf(back.y) < 0.99 else -node.global_basis.y
	back = Vector3(back.x, 0.0, back.z).normalized()
	if not back.is_finite() or back.is_zero_approx():
		return Basis.IDENTITY
	return Basis(Vector3.UP.cross(back), Vector3.UP, back)


## Gathers this tick's haptic frame, and pushes impacts for touches that began this tick.
func build_frame() -> HapticFrame3D:
	var to_view: Basis = view_basis().transposed()
	_contacts.resting_probe_distance = resting_probe_distance
	var above: Array[Dictionary] = _contacts.objects_above()
	var frame: HapticFrame3D = HapticFrame3D.new()
	var now: int = Engine.get_physics_frames()
	var seen: Dictionary[String, bool] = {}
	var faces: Array[Dictionary] = []
	var floor_normal: Vector3 = Vector3.ZERO
	for collision: Dictionary in _contacts.collisions(above):
		var key: String = collision["key"]
		var normal: Vector3 = collision["normal"]
		if seen.has(key) or frame.contacts.size() >= HapticFrameLimits.MAX_CONTACTS:
			continue
		seen[key] = true
		var material: HapticMaterial = _material_of(collision)
		if _new_face(faces, collision):
			var contact: HapticContact3D = HapticContact3D.new()
			contact.normal = to_view * normal
			contact.material = material.contact_material() if material != null else null
			frame.contacts.append(contact)
		if normal.dot(Vector3.UP) > floor_normal.dot(Vector3.UP):
			floor_normal = normal
		if _touches.touch(key, now, collision["id"], normal):
			_report_impact(collision, material, to_view)
	_touches.release(now, touch_release_s)
	var room: int = HapticFrameLimits.MAX_RESTING_OBJECTS
	for entry: Dictionary in above:
		var normal: Vector3 = entry["normal"]
		if frame.resting.size() < room:
			frame.resting.append(_load(to_view * normal, (entry["collider"] as RigidBody3D).mass))
	if own_weight_kg > 0.0 and floor_normal.dot(Vector3.UP) > 0.5 and frame.resting.size() < room:
		frame.resting.append(_load(to_view * -floor_normal, own_weight_kg))
	var water: Object = _water_area()
	if water != null:
		frame.in_water = true
		frame.water_drag_n_s_per_m = water.get(&"drag_coefficient")
		frame.water_inertia_n = water.get(&"inertia_force")
	frame.velocity_m_per_s = to_view * _body_velocity()
	_sequence += 1
	frame.sequence = _sequence
	frame.time_s = Time.get_ticks_msec() / 1000.0
	if _body is RigidBody3D:
		# What the next physics step starts from: a contact it finds is hit at this velocity.
		_velocity_before = PhysicsServer3D.body_get_direct_state(_body.get_rid()).linear_velocity
	return frame


## Plays a hit on the hand: a push along [param p_direction] (world space, from what hit
## toward the body) at [param p_speed_m_per_s], ringing like [param p_material] (null: the
## probe's default). The one line an [Area3D]'s handler needs, e.g.
## [code]body.get_node("HapticProbe3D").hit(Vector3.UP, 3.0)[/code].
func hit(p_direction: Vector3, p_speed_m_per_s: float, p_material: HapticMaterial = null) -> void:
	var direction_ok: bool = p_direction.is_finite() and not p_direction.is_zero_approx()
	if haptics == null or not direction_ok or p_speed_m_per_s <= 0.0:
		return
	var material: HapticMaterial = p_material if p_material != null else default_material
	var direction: Vector3 = view_basis().transposed() * p_direction.normalized()
	haptics.push_impact_3d(impact_event(direction, p_speed_m_per_s, material))


## The impact event for a push along [param p_direction] (view axes) at
## [param p_speed_m_per_s] ringing like [param p_material] (null: the servo's default).
static func impact_event(
	p_direction: Vector3, p_speed_m_per_s: float, p_material: HapticMaterial
) -> HapticImpact3D:
	var event: HapticImpact3D = HapticImpact3D.new()
	event.direction = p_direction
	event.speed_m_per_s = p_speed_m_per_s
	event.material = p_material.impact_material() if p_material != null else null
	return event


static func _load(normal: Vector3, mass_kg: float) -> HapticLoad3D:
	var out: HapticLoad3D = HapticLoad3D.new()
	out.normal = normal
	out.mass_kg = mass_kg
	return out


func _report_impact(collision: Dictionary, material: HapticMaterial, to_view: Basis) -> void:
	var normal: Vector3 = collision["normal"]
	var other_velocity: Vector3 = collision["velocity"]
	var speed: float = (other_velocity - _velocity_before).dot(normal)
	if speed < min_impact_speed:
		return
	impact.emit(collision["collider"], normal, speed)
	haptics.push_impact_3d(impact_event(to_view * normal, speed, material))


# Whether [param collision] is a face not yet in [param faces] (then added).
func _new_face(faces: Array[Dictionary], collision: Dictionary) -> bool:
	var id: int = collision["id"]
	var normal: Vector3 = collision["normal"]
	for face: Dictionary in faces:
		var face_normal: Vector3 = face["normal"]
		if face["id"] == id and face_normal.dot(normal) > SAME_FACE_COS:
			return false
	faces.append({"id": id, "normal": normal})
	return true


# The water volume the body is in, or null.
func _water_area() -> Object:
	_query.position = _body.global_position
	_query.collision_mask = 0xFFFFFFFF
	var space: PhysicsDirectSpaceState3D = _body.get_world_3d().direct_space_state
	for hit_area: Dictionary in space.intersect_point(_query, 8):
		var area: Object = hit_area.get("collider")
		if area != null and &"drag_coefficient" in area and &"inertia_force" in area:
			return area
	return null


# The touched shape's own HapticMaterial, else the collider's, else the touched GridMap
# cell's, else its PhysicsMaterial mapped, else the default.
func _material_of(collision: Dictionary) -> HapticMaterial:
	var collider: Object = collision["collider"]
	var declared: HapticMaterial = HapticMaterial.of_shape(collider, collision.get("shape", -1))
	if declared == null:
		declared = HapticMaterial.of(collider)
	if declared == null and collision.has("cell"):
		declared = HapticMaterial.of_grid_cell(collider as GridMap, collision["cell"])
	elif declared == null and collider is StaticBody3D:
		declared = _mapped((collider as StaticBody3D).physics_material_override)
	elif declared == null and collider is RigidBody3D:
		declared = _mapped((collider as RigidBody3D).physics_material_override)
	return declared if declared != null else default_material


func _mapped(physics: PhysicsMaterial) -> HapticMaterial:
	return HapticMaterial.from_physics_material(physics) if physics != null else null


func _body_velocity() -> Vector3:
	if _body is CharacterBody3D:
		return (_body as CharacterBody3D).velocity
	if _body is RigidBody3D:
		return (_body as RigidBody3D).linear_velocity
	return Vector3.ZERO
