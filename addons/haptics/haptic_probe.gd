@icon("res://addons/haptics/icons/haptic_probe.svg")
class_name HapticProbe
extends Node
## Drop-in haptics for any 2D body: add this node as a child of a [CharacterBody2D] or
## [RigidBody2D] and the body's contacts are felt.
##
## At every physics tick it gathers the body's contacts, one per touched shape or tile
## (normals and each one's [HapticMaterial]), dynamic bodies resting on it (mass and
## normal), the water volume it is in, its velocity, and the speed of new contacts; converts
## pixels to metres; and submits the frame and impact events to the haptics server. With
## [member drive_input] it also feeds the device's input vector to the body's
## [code]input_vector[/code] property before the body moves (acceleration control).
##
## Water volumes are [Area2D]s with [code]drag_coefficient[/code] and
## [code]inertia_force[/code] properties, such as the addon's [HapticWater].

## Emitted after each frame is submitted, with the frame as sent.
signal frame_submitted(frame: HapticFrame)
## Emitted when a new contact begins, with the approach speed in metres per second.
signal impact(collider: Object, normal: Vector2, speed: float)

## Earth's gravity, m/s², for [method pixels_per_metre_for_gravity].
const EARTH_GRAVITY := 9.80665
# The door's script, by its path next to this one rather than by the autoload's name: the
# editor parses this script as soon as the addon's folder appears, before enabling the plugin
# has registered the autoload (naming it then failed to parse, and the node could not be
# created until the editor was restarted).
const HapticsDoor := preload("haptics.gd")

## World scale: how many pixels make one metre.
@export_range(1.0, 10000.0, 1.0, "suffix:px/m") var pixels_per_metre: float = 100.0
## Material for bodies that declare none; [code]null[/code] uses the server's default.
@export var default_material: HapticMaterial = null
## Feed the device's input vector to the body's [code]input_vector[/code] property when
## the control mode is "device".
@export var drive_input: bool = true
## How far above the body to look for objects resting on it, in pixels.
@export_range(0.5, 16.0, 0.5, "suffix:px") var resting_probe_distance: float = 2.0
## Gravity platformers: while standing on a floor, the avatar's own weight presses the hand
## down with this mass × the servo's [code]force_model.gravity_n_per_kg[/code] (1 N/kg by
## default, so the value reads as newtons). 0 (the default) leaves standing still force-free.
@export_range(0.0, 10.0, 0.01, "suffix:kg") var own_weight_kg: float = 0.0
## Impacts slower than this are not played, in metres per second.
@export_range(0.0, 10.0, 0.01, "suffix:m/s") var min_impact_speed: float = 0.2

## A [code]HapticsServer[/code] of your own (a test steps one manually) to talk to instead
## of the [code]Haptics[/code] autoload's; set it before the probe enters the tree.
var server: Object = null
## The last frame submitted (for HUDs and tests).
var last_frame: HapticFrame = HapticFrame.new()
## Frames submitted so far.
var frames_submitted: int = 0

var _door: HapticsDoor = null
var _body: PhysicsBody2D = null
var _sequence: int = 0
var _velocity_before: Vector2 = Vector2.ZERO
var _touching: Dictionary[String, bool] = {}
var _query: PhysicsPointQueryParameters2D = PhysicsPointQueryParameters2D.new()
var _shape_query: PhysicsShapeQueryParameters2D = PhysicsShapeQueryParameters2D.new()
var _shape: CollisionShape2D = null
var _max_contacts: int = 0
var _max_resting: int = 0
var _floor_entry: Dictionary = {}
# The walls and ceilings (every slide contact but the floor) of the last frame.
var _sides: Array[Dictionary] = []


func _ready() -> void:
	_body = get_parent() as PhysicsBody2D
	if _body == null:
		push_error("HapticProbe must be a child of a CharacterBody2D or RigidBody2D.")
		set_physics_process(false)
		return
	_door = get_node_or_null(^"/root/Haptics") as HapticsDoor
	if _door == null:
		push_error(
			(
				"HapticProbe: no Haptics autoload; enable the Haptics plugin (Project Settings ▸ "
				+ "Plugins) or add it under [autoload] in project.godot (addon README)."
			)
		)
		set_physics_process(false)
		return
	if server == null:
		server = _door.get_server()
	_max_contacts = _door.get_constant(&"MAX_CONTACTS")
	_max_resting = _door.get_constant(&"MAX_RESTING_OBJECTS")
	if _body is RigidBody2D:
		var rigid: RigidBody2D = _body
		rigid.contact_monitor = true
		rigid.max_contacts_reported = maxi(rigid.max_contacts_reported, 8)
	for child: Node in _body.get_children():
		if child is CollisionShape2D and _shape == null:
			_shape = child
	if _shape == null:
		push_warning(
			(
				"HapticProbe: no CollisionShape2D on %s; objects resting on it are not felt."
				% _body.name
			)
		)
	_query.collide_with_areas = true
	_query.collide_with_bodies = false
	get_tree().physics_frame.connect(_before_bodies_move)


func _exit_tree() -> void:
	if get_tree().physics_frame.is_connected(_before_bodies_move):
		get_tree().physics_frame.disconnect(_before_bodies_move)


# Runs before any node's _physics_process: the body reads this tick's input vector, and the
# velocity it arrives with is what new contacts are hit at.
func _before_bodies_move() -> void:
	_velocity_before = _body_velocity()
	if not drive_input or server == null or not (&"input_vector" in _body):
		return
	# An unplugged device hands the player back to the keyboard until it returns.
	var device_driven: bool = (
		_door.control_mode == HapticsDoor.CONTROL_DEVICE and not _door.device.is_lost()
	)
	if &"use_keyboard" in _body:
		_body.set(&"use_keyboard", not device_driven)
	if device_driven:
		_body.set(&"input_vector", server.call(&"get_input_vector"))


func _physics_process(_delta: float) -> void:
	submit()


## Gathers this tick's frame and sends it to the server (what the probe does every physics
## tick), pushing impacts for contacts that began.
func submit() -> void:
	var frame: HapticFrame = build_frame()
	if server != null:
		server.call(&"submit_frame", frame.to_dictionary())
	last_frame = frame
	frames_submitted += 1
	frame_submitted.emit(frame)


## Gathers this tick's haptic frame, and pushes impacts for contacts that began this tick.
func build_frame() -> HapticFrame:
	var above: Array[Dictionary] = _objects_above()
	var frame: HapticFrame = HapticFrame.new()
	var contacts: Array[HapticContact] = frame.contacts
	var now_touching: Dictionary[String, bool] = {}
	# Faces already sent, by collider and normal: two floor tiles side by side are one
	# floor (each its own contact would count the floor's friction twice).
	var faces: Dictionary[String, bool] = {}
	var floor_normal: Vector2 = Vector2.ZERO
	for collision: Dictionary in _collisions(above):
		var key: String = collision["key"]
		var normal: Vector2 = collision["normal"]
		var face: String = "%d:%.2f,%.2f" % [collision["id"], normal.x, normal.y]
		if now_touching.has(key) or contacts.size() >= _max_contacts:
			continue
		now_touching[key] = true
		var material: HapticMaterial = _material_of(collision)
		if not faces.has(face):
			faces[face] = true
			contacts.append(HapticContact.new(normal, material))
		if normal.dot(Vector2.UP) > floor_normal.dot(Vector2.UP):
			floor_normal = normal
		if not _touching.has(key):
			var collider: Object = collision["collider"]
			_report_impact(collider, normal, material)
	_touching = now_touching
	_sequence += 1
	var resting: Array[HapticLoad] = frame.resting
	resting.assign(_resting_objects(above))
	if own_weight_kg > 0.0 and floor_normal.dot(Vector2.UP) > 0.5 and resting.size() < _max_resting:
		# The avatar's own weight, felt like an object resting on the hand: pressed along
		# the floor's normal into the floor.
		resting.append(HapticLoad.new(-floor_normal, own_weight_kg))
	var water: Object = _water_area()
	if water != null:
		frame.in_water = true
		frame.water_drag_n_s_per_m = water.get(&"drag_coefficient")
		frame.water_inertia_n = water.get(&"inertia_force")
	frame.velocity_m_per_s = _body_velocity() / pixels_per_metre
	frame.sequence = _sequence
	frame.time_s = Time.get_ticks_msec() / 1000.0
	return frame


## Pixels per metre for a game whose gravity is [param gravity_px_per_s2] (e.g. the
## project's [code]physics/2d/default_gravity[/code], or the player script's own gravity):
## the scale at which it falls like on Earth.
static func pixels_per_metre_for_gravity(gravity_px_per_s2: float) -> float:
	return gravity_px_per_s2 / EARTH_GRAVITY


# Each entry: collider, normal (from the surface toward the body), the world point of
# contact, and a key naming the touched shape (a tile on a TileMapLayer): contacts are one
# per shape, not per collider, as a tile map's floor and walls are one collider.
func _collisions(above: Array[Dictionary]) -> Array[Dictionary]:
	var out: Array[Dictionary] = []
	if _body is CharacterBody2D:
		var character: CharacterBody2D = _body
		var sides: Array[Dictionary] = []
		var reported: Dictionary[String, bool] = {}
		for i: int in character.get_slide_collision_count():
			var entry: Dictionary = _slide_entry(character.get_slide_collision(i))
			var floor_normal: Vector2 = character.get_floor_normal()
			var normal: Vector2 = entry["normal"]
			if character.is_on_floor() and normal.is_equal_approx(floor_normal):
				_floor_entry = entry
			else:
				sides.append(entry)
			reported[entry["key"]] = true
			out.append(entry)
		# Pressed into a wall, move_and_slide often reports only the wall although the body
		# still stands: the floor it last reported stays a contact while it does.
		if not character.is_on_floor():
			_floor_entry = {}
		elif not _floor_entry.is_empty() and is_instance_valid(_floor_entry["collider"]):
			out.append(_floor_entry)
		# A body whose speed into a wall builds up from 0 again after each hit (move_toward)
		# moves too little on some frames to reach it: move_and_slide reports no wall although
		# the body stays against it. A wall or ceiling of the last frame stays a contact while
		# the body still touches the same shape.
		for entry: Dictionary in _sides:
			if reported.has(entry["key"]):
				continue
			var kept: Dictionary = _still_touching(character, entry)
			if not kept.is_empty():
				reported[kept["key"]] = true
				sides.append(kept)
				out.append(kept)
		_sides = sides
	elif _body is RigidBody2D:
		var state: PhysicsDirectBodyState2D = PhysicsServer2D.body_get_direct_state(_body.get_rid())
		for i: int in state.get_contact_count():
			out.append(
				_entry(
					state.get_contact_collider_object(i),
					state.get_contact_collider(i),
					state.get_contact_collider_shape(i),
					state.get_contact_collider_position(i),
					state.get_contact_local_normal(i)
				)
			)
	for entry: Dictionary in above:
		var rigid: RigidBody2D = entry["collider"]
		var normal: Vector2 = entry["normal"]
		out.append(_entry(rigid, rigid.get_rid(), -1, rigid.global_position, normal))
	return out


func _slide_entry(collision: KinematicCollision2D) -> Dictionary:
	return _entry(
		collision.get_collider(),
		collision.get_collider_rid(),
		collision.get_collider_shape_index(),
		collision.get_position(),
		collision.get_normal()
	)


# The contact [param entry] again when the body, moved by its safe margin toward it, touches
# the same shape (or tile); empty once it has moved away.
func _still_touching(character: CharacterBody2D, entry: Dictionary) -> Dictionary:
	if not is_instance_valid(entry["collider"]):
		return {}
	var normal: Vector2 = entry["normal"]
	var collision: KinematicCollision2D = KinematicCollision2D.new()
	var margin: float = character.safe_margin
	if not character.test_move(character.global_transform, -normal * margin, collision, margin):
		return {}
	var touched: Dictionary = _slide_entry(collision)
	return touched if touched["key"] == entry["key"] else {}


func _entry(collider: Object, rid: RID, shape: int, point: Vector2, normal: Vector2) -> Dictionary:
	var id: int = collider.get_instance_id() if collider != null else 0
	var entry: Dictionary = {"collider": collider, "normal": normal, "id": id}
	var tiles: TileMapLayer = collider as TileMapLayer
	if tiles != null:
		# Half a pixel behind the surface lies the touched tile, whichever physics quadrant
		# (body) holds its shape.
		var cell: Vector2i = tiles.local_to_map(tiles.to_local(point - normal * 0.5))
		entry["cell"] = cell
		entry["key"] = "%d:%d,%d" % [id, cell.x, cell.y]
	else:
		entry["key"] = "%d:%d:%d" % [id, rid.get_id(), shape]
	return entry


# Rigid bodies touching the top of the body: the body's shape swept a little upward finds
# them, then each one is asked alone (all others excluded) for its surface normal, which
# points from it toward the body. Each entry: collider, normal.
func _objects_above() -> Array[Dictionary]:
	var out: Array[Dictionary] = []
	if _shape == null:
		return out
	_shape_query.shape = _shape.shape
	_shape_query.transform = _shape.global_transform
	_shape_query.motion = Vector2.UP * resting_probe_distance
	_shape_query.collision_mask = _body.collision_mask
	_shape_query.exclude = [_body.get_rid()]
	var space: PhysicsDirectSpaceState2D = _body.get_world_2d().direct_space_state
	var hits: Array[Dictionary] = space.intersect_shape(_shape_query, 8)
	var all_rids: Array[RID] = [_body.get_rid()]
	for hit: Dictionary in hits:
		all_rids.append(hit["rid"])
	for hit: Dictionary in hits:
		var collider: Object = hit["collider"]
		var rigid: RigidBody2D = collider as RigidBody2D
		if rigid == null:
			continue
		var others: Array[RID] = all_rids.duplicate()
		others.erase(hit["rid"])
		_shape_query.exclude = others
		var info: Dictionary = space.get_rest_info(_shape_query)
		var normal: Vector2 = info.get("normal", Vector2.ZERO)
		if not normal.is_zero_approx():
			out.append({"collider": rigid, "normal": normal})
	return out


func _resting_objects(above: Array[Dictionary]) -> Array[HapticLoad]:
	var out: Array[HapticLoad] = []
	for entry: Dictionary in above:
		var rigid: RigidBody2D = entry["collider"]
		if out.size() < _max_resting:
			out.append(HapticLoad.new(entry["normal"], rigid.mass))
	return out


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


func _report_impact(collider: Object, normal: Vector2, material: HapticMaterial) -> void:
	var other_velocity: Vector2 = Vector2.ZERO
	if collider is RigidBody2D:
		other_velocity = (collider as RigidBody2D).linear_velocity
	var speed: float = (other_velocity - _velocity_before).dot(normal) / pixels_per_metre
	if speed < min_impact_speed:
		return
	impact.emit(collider, normal, speed)
	if server != null:
		server.call(&"push_impact", HapticImpact.new(normal, speed, material).to_dictionary())


# The collider's own HapticMaterial, else the touched tile's (HapticMaterial.of_tile), else
# its PhysicsMaterial mapped (HapticMaterial.from_physics_material), else the default.
func _material_of(collision: Dictionary) -> HapticMaterial:
	var collider: Object = collision["collider"]
	var declared: HapticMaterial = HapticMaterial.of(collider)
	if declared == null and collision.has("cell"):
		var cell: Vector2i = collision["cell"]
		declared = HapticMaterial.of_tile(collider as TileMapLayer, cell)
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
