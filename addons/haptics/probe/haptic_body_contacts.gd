extends RefCounted
## What a [HapticProbe]'s body touches on one physics tick: its contacts (a
## [CharacterBody2D]'s slide collisions, a [RigidBody2D]'s reported contacts) and the rigid
## bodies resting on top of it. Each entry is a [Dictionary]: [code]collider[/code],
## [code]normal[/code] (unit, from the surface toward the body), [code]id[/code] (the
## collider's instance id), [code]key[/code] (names the touched shape, or the tile of a
## [TileMapLayer]: one collider holds every tile), [code]shape[/code] (the touched shape's
## index in the collider), [code]velocity[/code] (the collider's own at the contact, pixels
## per second) and, on tiles, [code]cell[/code] and [code]tiles[/code] (the [TileMapLayer]
## holding it: the collider, or the layer of a [TileMap] collider).

const HapticBodyShapes := preload("res://addons/haptics/probe/haptic_body_shapes.gd")
## An object above the body rests on it when its surface normal points at least this much
## down (60° from vertical): the floor under the feet, found by a downward ray or a shape
## reaching below the body, is no load.
const MIN_DOWNWARD := 0.5
## Bodies the upward query looks at, per shape.
const MAX_HITS := 8

## How far above the body to look for objects resting on it, in pixels.
var resting_probe_distance: float = 2.0
## The body's own shapes as of the last tick (the solid ones are searched above).
var shapes: HapticBodyShapes = null

var _body: PhysicsBody2D = null
var _query: PhysicsShapeQueryParameters2D = PhysicsShapeQueryParameters2D.new()
var _floor_entry: Dictionary = {}
# The walls and ceilings (every slide contact but the floor) of the last frame.
var _sides: Array[Dictionary] = []
# Tile colliders whose touched tile could not be found, warned about once.
var _unread: Dictionary[int, bool] = {}


func _init(p_body: PhysicsBody2D) -> void:
	_body = p_body
	shapes = HapticBodyShapes.new(p_body)


## The body's contacts this tick, then those of [param above] (from [method objects_above])
## it does not touch already.
func collisions(above: Array[Dictionary]) -> Array[Dictionary]:
	var out: Array[Dictionary] = []
	if _body is CharacterBody2D:
		out = _character_collisions(_body as CharacterBody2D)
	elif _body is RigidBody2D:
		var state: PhysicsDirectBodyState2D = PhysicsServer2D.body_get_direct_state(_body.get_rid())
		for i: int in state.get_contact_count():
			out.append(
				entry(
					state.get_contact_collider_object(i),
					state.get_contact_collider(i),
					state.get_contact_collider_shape(i),
					state.get_contact_collider_position(i),
					state.get_contact_local_normal(i),
					state.get_contact_collider_velocity_at_position(i)
				)
			)
	# A body resting on top is a contact too; the body's own contacts may already hold it
	# (a rigid body's do), at another of its shapes or points: once is enough.
	var touched: Dictionary[int, bool] = {}
	for contact: Dictionary in out:
		touched[contact["id"]] = true
	for resting: Dictionary in above:
		if not touched.has(resting["id"]):
			out.append(resting)
	return out


## Rigid bodies resting on top of the body: each solid shape swept a little upward finds
## them, then each one alone (all others excluded) gives its surface normal, which points
## from it toward the body; only those pressing from above are kept.
func objects_above() -> Array[Dictionary]:
	var out: Array[Dictionary] = []
	# Read again each tick: a game may move, turn off or swap its shapes.
	shapes = HapticBodyShapes.new(_body)
	if shapes.solid.is_empty():
		return out
	var space: PhysicsDirectSpaceState2D = _body.get_world_2d().direct_space_state
	var own: RID = _body.get_rid()
	var all_rids: Array[RID] = [own]
	var only_own: Array[RID] = [own]
	var candidates: Dictionary[RID, RigidBody2D] = {}
	for solid: Dictionary in shapes.solid:
		_aim(solid, only_own)
		for hit: Dictionary in space.intersect_shape(_query, MAX_HITS):
			var rid: RID = hit["rid"]
			if not all_rids.has(rid):
				all_rids.append(rid)
			var collider: Object = hit["collider"]
			var rigid: RigidBody2D = collider as RigidBody2D
			if rigid != null:
				candidates[rid] = rigid
	for rid: RID in candidates:
		var others: Array[RID] = all_rids.duplicate()
		others.erase(rid)
		for solid: Dictionary in shapes.solid:
			_aim(solid, others)
			var info: Dictionary = space.get_rest_info(_query)
			var normal: Vector2 = info.get("normal", Vector2.ZERO)
			if normal.dot(Vector2.DOWN) < MIN_DOWNWARD:
				continue
			var velocity: Vector2 = info["linear_velocity"]
			var shape: int = info["shape"]
			var point: Vector2 = info["point"]
			out.append(entry(candidates[rid], rid, shape, point, normal, velocity))
			break
	return out


## One contact's entry (see the class description).
func entry(
	p_collider: Object,
	p_rid: RID,
	p_shape: int,
	p_point: Vector2,
	p_normal: Vector2,
	p_velocity: Vector2 = Vector2.ZERO
) -> Dictionary:
	var id: int = p_collider.get_instance_id() if p_collider != null else 0
	var out: Dictionary = {
		"collider": p_collider,
		"normal": p_normal,
		"id": id,
		"velocity": p_velocity,
		"shape": p_shape
	}
	# Half a pixel behind the surface lies the touched tile, whichever physics quadrant
	# (body) holds its shape.
	var behind: Vector2 = p_point - p_normal * 0.5
	var tiles: TileMapLayer = _layer_touched(p_collider, behind)
	if tiles == null and p_collider is TileMap and not _unread.has(id):
		_unread[id] = true
		push_warning(
			(
				"HapticProbe: no tile of %s found at %s; it feels like the probe's default material."
				% [(p_collider as Node).name, behind]
			)
		)
	if tiles != null:
		var cell: Vector2i = tiles.local_to_map(tiles.to_local(behind))
		out["cell"] = cell
		out["tiles"] = tiles
		out["key"] = "%d:%d,%d" % [id, cell.x, cell.y]
	else:
		out["key"] = "%d:%d:%d" % [id, p_rid.get_id(), p_shape]
	return out


# The tile layer whose tile lies at [param point]: a [TileMapLayer] collider itself, or
# the layer of a [TileMap] (Godot 4.0-4.2's node: it keeps its layers as internal
# TileMapLayer children) that has a tile there; null for any other collider.
static func _layer_touched(p_collider: Object, p_point: Vector2) -> TileMapLayer:
	if p_collider is TileMapLayer:
		return p_collider as TileMapLayer
	if not p_collider is TileMap:
		return null
	for child: Node in (p_collider as TileMap).get_children(true):
		var layer: TileMapLayer = child as TileMapLayer
		var here: Vector2 = layer.to_local(p_point) if layer != null else Vector2.ZERO
		if layer != null and layer.get_cell_tile_data(layer.local_to_map(here)) != null:
			return layer
	return null


func _aim(solid: Dictionary, exclude: Array[RID]) -> void:
	var local: Transform2D = solid["transform"]
	var shape: Shape2D = solid["shape"]
	_query.shape = shape
	_query.transform = _body.global_transform * local
	_query.motion = Vector2.UP * resting_probe_distance
	_query.collision_mask = _body.collision_mask
	_query.exclude = exclude


func _character_collisions(character: CharacterBody2D) -> Array[Dictionary]:
	var out: Array[Dictionary] = []
	var sides: Array[Dictionary] = []
	var reported: Dictionary[String, bool] = {}
	for i: int in character.get_slide_collision_count():
		var slide: Dictionary = _slide_entry(character.get_slide_collision(i))
		var floor_normal: Vector2 = character.get_floor_normal()
		var normal: Vector2 = slide["normal"]
		if character.is_on_floor() and normal.is_equal_approx(floor_normal):
			_floor_entry = slide
		else:
			sides.append(slide)
		reported[slide["key"]] = true
		out.append(slide)
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
	for side: Dictionary in _sides:
		if reported.has(side["key"]):
			continue
		var kept: Dictionary = _still_touching(character, side)
		if not kept.is_empty():
			reported[kept["key"]] = true
			sides.append(kept)
			out.append(kept)
	_sides = sides
	return out


func _slide_entry(collision: KinematicCollision2D) -> Dictionary:
	return entry(
		collision.get_collider(),
		collision.get_collider_rid(),
		collision.get_collider_shape_index(),
		collision.get_position(),
		collision.get_normal(),
		collision.get_collider_velocity()
	)


# The contact [param side] again when the body, moved by its safe margin toward it, touches
# the same shape (or tile); empty once it has moved away.
func _still_touching(character: CharacterBody2D, side: Dictionary) -> Dictionary:
	if not is_instance_valid(side["collider"]):
		return {}
	var normal: Vector2 = side["normal"]
	var collision: KinematicCollision2D = KinematicCollision2D.new()
	var margin: float = character.safe_margin
	if not character.test_move(character.global_transform, -normal * margin, collision, margin):
		return {}
	var touched: Dictionary = _slide_entry(collision)
	return touched if touched["key"] == side["key"] else {}
