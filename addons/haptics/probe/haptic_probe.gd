@icon("res://addons/haptics/icons/haptic_probe.svg")
class_name HapticProbe
extends Node
## Drop-in haptics for any 2D body: add this node as a child of a [CharacterBody2D] or
## [RigidBody2D] and the body's contacts are felt.
##
## At every physics tick it gathers the body's contacts, one per touched shape or tile
## (normals and each one's [HapticMaterial]), dynamic bodies resting on top of the body's own
## shapes (mass and normal), the water volume it is in, its velocity, and the speed of new
## touches; converts pixels to metres; and submits the frame and impact events to the
## haptics servo. With [member drive_input] it also feeds the device's input vector to the
## body's [code]input_vector[/code] property before the body moves (acceleration control).
## [br][br]
## Impact speeds are taken from the velocity before the collision: a character's at the start
## of the tick, a rigid body's as it entered the physics step that found the contact (Godot
## has already resolved the collision when its velocity is read next), relative to the
## collider's own velocity at the contact (a moving platform).
##
## Water volumes are [Area2D]s with [code]drag_coefficient[/code] and
## [code]inertia_force[/code] properties, such as the addon's [HapticWater].

## Emitted after each frame is submitted, with the frame as sent.
signal frame_submitted(frame: HapticFrame)
## Emitted when a new touch begins, with the approach speed in metres per second.
signal impact(collider: Object, normal: Vector2, speed: float)

## Earth's gravity, m/s², for [method pixels_per_metre_for_gravity].
const EARTH_GRAVITY := 9.80665
## Contact normals of one collider closer than this (cosine) are one face: two floor tiles
## side by side, two contact points of one plank, are one floor.
const SAME_FACE_COS := 0.999
# The door's script, by its path next to this one rather than by the autoload's name: the
# editor parses this script as soon as the addon's folder appears, before enabling the plugin
# has registered the autoload (naming it then failed to parse, and the node could not be
# created until the editor was restarted).
const Haptics := preload("res://addons/haptics/door/haptics.gd")
const HapticsLookup := preload("res://addons/haptics/door/haptics_lookup.gd")
const HapticBodyContacts := preload("res://addons/haptics/probe/haptic_body_contacts.gd")
const HapticBodyShapes := preload("res://addons/haptics/probe/haptic_body_shapes.gd")
const HapticTouches := preload("res://addons/haptics/probe/haptic_touches.gd")

## World scale: how many pixels make one metre. The rule: the gravity your body falls with
## (px/s²) divided by 9.81 ([method pixels_per_metre_for_gravity]), so that a fall lasting a
## second hits as fast as one on Earth. At start the probe prints the height this gives the
## body ([member report_scale]).
@export_range(1.0, 10000.0, 0.1, "suffix:px/m") var pixels_per_metre: float = 100.0
## Material for bodies that declare none; [code]null[/code] uses the servo's default.
@export var default_material: HapticMaterial = null
## Feed the device's input vector to the body's [code]input_vector[/code] property when
## the control mode is "device".
@export var drive_input: bool = true
## How far above the body to look for objects resting on it, in pixels.
@export_range(0.5, 16.0, 0.5, "suffix:px") var resting_probe_distance: float = 2.0
## Gravity platformers: while standing on a floor, the avatar's own weight presses the hand
## down with this mass × the movement renderer's
## [member HapticForceModelSettings.gravity_n_per_kg] (1 N/kg by
## default, so the value reads as newtons). 0 (the default) leaves standing still force-free.
@export_range(0.0, 10.0, 0.01, "suffix:kg") var own_weight_kg: float = 0.0
## Impacts slower than this are not played, in metres per second.
@export_range(0.0, 10.0, 0.01, "suffix:m/s") var min_impact_speed: float = 0.2
## A shape lost for less than this and touched again is the same touch, not a new impact: a
## rigid body riding a moving platform loses and regains it every few frames.
@export_range(0.0, 1.0, 0.01, "suffix:s") var touch_release_s: float = 0.1
## Print at start the height [member pixels_per_metre] gives the body (debug builds).
@export var report_scale: bool = true

## The door this probe hands its frames and impacts to: the [code]Haptics[/code] autoload
## unless set before the probe enters the tree (a test gives it a door of its own, whose
## servo it steps itself).
var haptics: Haptics = null
## The last frame submitted (for HUDs and tests).
var last_frame: HapticFrame = HapticFrame.new()
## Frames submitted so far.
var frames_submitted: int = 0
## The warning given at start about the body's shapes (a ray skipped, no solid shape);
## empty when there was none.
var shape_warning: String = ""

var _body: PhysicsBody2D = null
var _contacts: HapticBodyContacts = null
var _sequence: int = 0
var _velocity_before: Vector2 = Vector2.ZERO
var _touches: HapticTouches = HapticTouches.new()
var _query: PhysicsPointQueryParameters2D = PhysicsPointQueryParameters2D.new()


func _ready() -> void:
	_body = get_parent() as PhysicsBody2D
	if _body == null:
		push_error("HapticProbe must be a child of a CharacterBody2D or RigidBody2D.")
		set_physics_process(false)
		return
	if haptics == null:
		haptics = HapticsLookup.autoload_for(self, "HapticProbe")
	if haptics == null:
		set_physics_process(false)
		return
	if _body is RigidBody2D:
		var rigid: RigidBody2D = _body
		rigid.contact_monitor = true
		rigid.max_contacts_reported = maxi(rigid.max_contacts_reported, 8)
	_contacts = HapticBodyContacts.new(_body)
	shape_warning = _shapes_warning()
	if not shape_warning.is_empty():
		push_warning(shape_warning)
	if report_scale and OS.is_debug_build():
		print(scale_report())
	_query.collide_with_areas = true
	_query.collide_with_bodies = false
	get_tree().physics_frame.connect(_before_bodies_move)


func _exit_tree() -> void:
	if get_tree().physics_frame.is_connected(_before_bodies_move):
		get_tree().physics_frame.disconnect(_before_bodies_move)


# Runs before any node's _physics_process: the body reads this tick's input vector, and a
# character's velocity as it arrives is what new contacts are hit at.
func _before_bodies_move() -> void:
	if _body is CharacterBody2D:
		_velocity_before = (_body as CharacterBody2D).velocity
	if not drive_input or not (&"input_vector" in _body):
		return
	# An unplugged device hands the player back to the keyboard until it returns.
	var device_driven: bool = (
		haptics.control_mode == Haptics.CONTROL_DEVICE and not haptics.device.is_lost()
	)
	if &"use_keyboard" in _body:
		_body.set(&"use_keyboard", not device_driven)
	if device_driven:
		_body.set(&"input_vector", haptics.get_input_vector())


func _physics_process(_delta: float) -> void:
	submit()


## Gathers this tick's frame and hands it to the door (what the probe does every physics
## tick), pushing impacts for touches that began.
func submit() -> void:
	var frame: HapticFrame = build_frame()
	haptics.submit_frame(frame)
	last_frame = frame
	frames_submitted += 1
	frame_submitted.emit(frame)


## Gathers this tick's haptic frame, and pushes impacts for touches that began this tick.
func build_frame() -> HapticFrame:
	_contacts.resting_probe_distance = resting_probe_distance
	var above: Array[Dictionary] = _contacts.objects_above()
	var frame: HapticFrame = HapticFrame.new()
	var contacts: Array[HapticContact] = frame.contacts
	var now: int = Engine.get_physics_frames()
	var seen: Dictionary[String, bool] = {}
	# Faces already sent (collider id and normal): each its own contact would count one
	# floor's friction twice.
	var faces: Array[Dictionary] = []
	var floor_normal: Vector2 = Vector2.ZERO
	for collision: Dictionary in _contacts.collisions(above):
		var key: String = collision["key"]
		var normal: Vector2 = collision["normal"]
		if seen.has(key) or contacts.size() >= HapticFrameLimits.MAX_CONTACTS:
			continue
		seen[key] = true
		var material: HapticMaterial = _material_of(collision)
		if _new_face(faces, collision):
			var contact: HapticContact = HapticContact.new()
			contact.normal = normal
			contact.material = material.contact_material() if material != null else null
			contacts.append(contact)
		if normal.dot(Vector2.UP) > floor_normal.dot(Vector2.UP):
			floor_normal = normal
		var id: int = collision["id"]
		if _touches.touch(key, now, id, Vector3(normal.x, normal.y, 0.0)):
			_report_impact(collision, material)
	_touches.release(now, touch_release_s)
	_sequence += 1
	var resting: Array[HapticLoad] = frame.resting
	var room: int = HapticFrameLimits.MAX_RESTING_OBJECTS
	for entry: Dictionary in above:
		var rigid: RigidBody2D = entry["collider"]
		var normal: Vector2 = entry["normal"]
		if resting.size() < room:
			resting.append(_load(normal, rigid.mass))
	if own_weight_kg > 0.0 and floor_normal.dot(Vector2.UP) > 0.5 and resting.size() < room:
		# The avatar's own weight, felt like an object resting on the hand: pressed along
		# the floor's normal into the floor.
		resting.append(_load(-floor_normal, own_weight_kg))
	var water: Object = _water_area()
	if water != null:
		frame.in_water = true
		frame.water_drag_n_s_per_m = water.get(&"drag_coefficient")
		frame.water_inertia_n = water.get(&"inertia_force")
	frame.velocity_m_per_s = _body_velocity() / pixels_per_metre
	frame.sequence = _sequence
	frame.time_s = Time.get_ticks_msec() / 1000.0
	if _body is RigidBody2D:
		# What the physics step after this tick's scripts starts from: a contact it finds
		# is reported next tick, hit at this velocity.
		_velocity_before = PhysicsServer2D.body_get_direct_state(_body.get_rid()).linear_velocity
	return frame


## Pixels per metre for a game whose gravity is [param gravity_px_per_s2] (e.g. the
## project's [code]physics/2d/default_gravity[/code], or the player script's own gravity):
## the scale at which it falls like on Earth.
static func pixels_per_metre_for_gravity(gravity_px_per_s2: float) -> float:
	return gravity_px_per_s2 / EARTH_GRAVITY


## The body's height at [member pixels_per_metre], in metres: the span of its collision
## shapes (rays included), 0 before the probe is ready or without shapes.
func body_height_m() -> float:
	if _contacts == null:
		return 0.0
	return _contacts.shapes.bounds.size.y / pixels_per_metre


## The scale check printed at start: the body's height at [member pixels_per_metre], and
## the scale the rule gives for the project's gravity. Too tall or too short a body for what
## it stands for does not mean the scale is wrong (many games draw a world out of scale);
## a scale far from the rule's makes impacts harder or softer than the falls look.
func scale_report() -> String:
	var gravity: float = ProjectSettings.get_setting("physics/2d/default_gravity", 980.0)
	var height_px: float = 0.0 if _contacts == null else _contacts.shapes.bounds.size.y
	return (
		(
			"HapticProbe: at %.1f px/m %s is %.2f m tall (%.0f px); the rule, gravity / 9.81, "
			+ "gives %.1f px/m for the project's gravity of %.0f px/s²."
		)
		% [
			pixels_per_metre,
			str(_body.name) if _body != null else "the body",
			height_px / pixels_per_metre,
			height_px,
			pixels_per_metre_for_gravity(gravity),
			gravity,
		]
	)


func _shapes_warning() -> String:
	var shapes: HapticBodyShapes = _contacts.shapes
	var solid: Array[Dictionary] = shapes.solid
	var skipped: PackedStringArray = shapes.skipped
	if solid.is_empty():
		return (
			"HapticProbe: no solid collision shape on %s (%s); objects resting on it are not felt."
			% [_body.name, "only " + ", ".join(skipped) if not skipped.is_empty() else "none"]
		)
	if skipped.is_empty():
		return ""
	var used: PackedStringArray = []
	for entry: Dictionary in solid:
		var owner_object: Object = entry["owner"]
		var owner_node: Node = owner_object as Node
		var owner_name: String = str(owner_node.name) if owner_node != null else "?"
		if not used.has(owner_name):
			used.append(owner_name)
	return (
		(
			"HapticProbe: %s's %s is not the body's outline (it reaches into what the body "
			+ "stands on); objects resting on it are found above %s instead."
		)
		% [_body.name, ", ".join(skipped), ", ".join(used)]
	)


# Whether [param collision] is a face not yet in [param faces] (then added): one collider's
# contacts with the same normal are one face, compared as numbers (a printed -0.00 and 0.00
# are the same normal).
func _new_face(faces: Array[Dictionary], collision: Dictionary) -> bool:
	var id: int = collision["id"]
	var normal: Vector2 = collision["normal"]
	for face: Dictionary in faces:
		var face_normal: Vector2 = face["normal"]
		if face["id"] == id and face_normal.dot(normal) > SAME_FACE_COS:
			return false
	faces.append({"id": id, "normal": normal})
	return true


# The water volume the body is in, or null.
func _water_area() -> Object:
	_query.position = _body.global_position
	_query.collision_mask = 0xFFFFFFFF
	var space: PhysicsDirectSpaceState2D = _body.get_world_2d().direct_space_state
	for hit: Dictionary in space.intersect_point(_query, 8):
		var area: Object = hit.get("collider")
		if area != null and &"drag_coefficient" in area and &"inertia_force" in area:
			return area
	return null


func _report_impact(collision: Dictionary, material: HapticMaterial) -> void:
	var normal: Vector2 = collision["normal"]
	var other_velocity: Vector2 = collision["velocity"]
	var speed: float = (other_velocity - _velocity_before).dot(normal) / pixels_per_metre
	if speed < min_impact_speed:
		return
	var collider: Object = collision["collider"]
	impact.emit(collider, normal, speed)
	haptics.push_impact(impact_event(normal, speed, material))


## Plays a hit on the hand: a push along [param p_direction] (from what hit toward the body)
## at [param p_speed_m_per_s], ringing like [param p_material] (null: the probe's default).
## The one line a kill zone, a spike or an enemy's handler needs for what the body's own
## contacts do not report (an [Area2D] it entered), e.g.
## [code]body.get_node("HapticProbe").hit(Vector2.UP, 3.0)[/code].
func hit(p_direction: Vector2, p_speed_m_per_s: float, p_material: HapticMaterial = null) -> void:
	var material: HapticMaterial = p_material if p_material != null else default_material
	play_hit(haptics, p_direction, p_speed_m_per_s, material)


## Pushes the hit of [method hit] to [param door]; nothing for a door of null, a zero or
## non-finite direction, or a speed that is not positive. Both probes' one way to a hit.
static func play_hit(
	door: Haptics, p_direction: Vector2, p_speed_m_per_s: float, p_material: HapticMaterial
) -> void:
	var direction_ok: bool = p_direction.is_finite() and not p_direction.is_zero_approx()
	if door != null and direction_ok and p_speed_m_per_s > 0.0:
		door.push_impact(impact_event(p_direction.normalized(), p_speed_m_per_s, p_material))


## The impact event for a push along [param p_direction] at [param p_speed_m_per_s] ringing
## like [param p_material] (null: the servo's default).
static func impact_event(
	p_direction: Vector2, p_speed_m_per_s: float, p_material: HapticMaterial
) -> HapticImpact:
	var event: HapticImpact = HapticImpact.new()
	event.direction = p_direction
	event.speed_m_per_s = p_speed_m_per_s
	event.material = p_material.impact_material() if p_material != null else null
	return event


static func _load(normal: Vector2, mass_kg: float) -> HapticLoad:
	var out: HapticLoad = HapticLoad.new()
	out.normal = normal
	out.mass_kg = mass_kg
	return out


# The touched shape's own HapticMaterial, else the collider's, else the touched tile's
# (HapticMaterial.of_tile), else its PhysicsMaterial mapped
# (HapticMaterial.from_physics_material), else the default.
func _material_of(collision: Dictionary) -> HapticMaterial:
	var collider: Object = collision["collider"]
	var declared: HapticMaterial = HapticMaterial.of_shape(collider, collision.get("shape", -1))
	if declared == null:
		declared = HapticMaterial.of(collider)
	if declared == null and collision.has("cell"):
		var cell: Vector2i = collision["cell"]
		declared = HapticMaterial.of_tile(collision["tiles"] as TileMapLayer, cell)
	elif declared == null and collider is StaticBody2D:
		declared = _mapped((collider as StaticBody2D).physics_material_override)
	elif declared == null and collider is RigidBody2D:
		declared = _mapped((collider as RigidBody2D).physics_material_override)
	return declared if declared != null else default_material


func _mapped(physics: PhysicsMaterial) -> HapticMaterial:
	return HapticMaterial.from_physics_material(physics) if physics != null else null


func _body_velocity() -> Vector2:
	if _body is CharacterBody2D:
		return (_body as CharacterBody2D).velocity
	if _body is RigidBody2D:
		return (_body as RigidBody2D).linear_velocity
	return Vector2.ZERO
