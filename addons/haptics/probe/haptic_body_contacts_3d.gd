extends RefCounted
## What a [HapticProbe3D]'s body touches on one physics tick: its contacts (a
## [CharacterBody3D]'s slide collisions, a [RigidBody3D]'s reported contacts) and the rigid
## bodies resting on top of it. Each entry is a [Dictionary]: [code]collider[/code],
## [code]normal[/code] (unit, world space, from the surface toward the body), [code]id[/code]
## (the collider's instance id), [code]key[/code] (names the touched shape, or the cell of a
## [GridMap]: one collider holds every cell), [code]shape[/code] (the touched shape's index in
## the collider), [code]velocity[/code] (the collider's own at the contact, m/s) and, on a
## [GridMap], [code]cell[/code].

## An object above the body rests on it when its surface normal points at least this much
## down (60° from vertical): the floor under the feet is no load.
const MIN_DOWNWARD := 0.5
## Bodies the upward query looks at, per shape.
const MAX_HITS := 8
## How far behind a GridMap's surface its touched cell is looked for, in metres.
const CELL_DEPTH_M := 0.01

## How far above the body to look for objects resting on it, in metres.
var resting_probe_distance: float = 0.02

var _body: PhysicsBody3D = null
var _query: PhysicsShapeQueryParameters3D = PhysicsShapeQueryParameters3D.new()
var _floor_entry: Dictionary = {}
# The walls and ceilings (every slide contact but the floor) of the last frame.
var _sides: Array[Dictionary] = []


func _init(p_body: PhysicsBody3D) -> void:
	_body = p_body


## The body's solid collision shapes: each [code]shape[/code] with its body-local
## [code]transform[/code]. Rays and world boundaries are no outline (a ray reaches into what
## the body stands on).
func solid_shapes() -> Array[Dictionary]:
	var out: Array[Dictionary] = []
	for owner_id: int in _body.get_shape_owners():
		if _body.is_shape_owner_disabled(owner_id):
			continue
		var local: Transform3D = _body.shape_owner_get_transform(owner_id)
		for i: int in _body.shape_owner_get_shape_count(owner_id):
			var shape: Shape3D = _body.shape_owner_get_shape(owner_id, i)
			if not (shape is SeparationRayShape3D or shape is WorldBoundaryShape3D):
				out.append({"shape": shape, "transform": local})
	return out


## The body's contacts this tick, then those of [param above] (from [method objects_above])
## it does not touch already.
func collisions(above: Array[Dictionary]) -> Array[Dictionary]:
	var out: Array[Dictionary] = []
	if _body is CharacterBody3D:
		out = _character_collisions(_body as CharacterBody3D)
	elif _body is RigidBody3D:
		var state: PhysicsDirectBodyState3D = PhysicsServer3D.body_get_direct_state(_body.get_rid())
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
	var solid: Array[Dictionary] = solid_shapes()
	var space: PhysicsDirectSpaceState3D = _body.get_world_3d().direct_space_state
	var own: RID = _body.get_rid()
	var all_rids: Array[RID] = [own]
	var candidates: Dictionary[RID, RigidBody3D] = {}
	for shape: Dictionary in solid:
		_aim(shape, [own])
		for hit: Dictionary in space.intersect_shape(_query, MAX_HITS):
			var rid: RID = hit["rid"]
			if not all_rids.has(rid):
				all_rids.append(rid)
			var rigid: RigidBody3D = hit["collider"] as RigidBody3D
			if rigid != null:
				candidates[rid] = rigid
	for rid: RID in candidates:
		var others: Array[RID] = all_rids.duplicate()
		others.erase(rid)
		for shape: Dictionary in solid:
			_aim(shape, others)
			var info: Dictionary = space.get_rest_info(_query)
			var normal: Vector3 = info.get("normal", Vector3.ZERO)
			if normal.dot(Vector3.DOWN) < MIN_DOWNWARD:
				continue
			var point: Vector3 = info["point"]
			var velocity: Vector3 = info["linear_velocity"]
			out.append(entry(candidates[rid], rid, info["shape"], point, normal, velocity))
			break
	return out


## One contact's entry (see the class description).
func entry(
	p_collider: Object,
	p_rid: RID,
	p_shape: int,
	p_point: Vector3,
	p_normal: Vector3,
	p_velocity: Vector3 = Vector3.ZERO
) -> Dictionary:
	var id: int = p_collider.get_instance_id() if p_collider != null else 0
	var out: Dictionary = {
		"collider": p_collider,
		"normal": p_normal.normalized(),
		"id": id,
		"velocity": p_velocity,
		"shape": p_shape
	}
	var grid: GridMap = p_collider as GridMap
	var cell: Vector3i = Vector3i.ZERO
	if grid != null:
		cell = grid.local_to_map(grid.to_local(p_point - p_normal.normalized() * CELL_DEPTH_M))
	if grid != null and grid.get_cell_item(cell) != GridMap.INVALID_CELL_ITEM:
		out["cell"] = cell
		out["key"] = "%d:%d,%d,%d" % [id, cell.x, cell.y, cell.z]
	else:
		out["key"] = "%d:%d:%d" % [id, p_rid.get_id(), p_shape]
	return out


func _aim(shape: Dictionary, exclude: Array[RID]) -> void:
	var local: Transform3D = shape["transform"]
	_query.shape = shape["shape"]
	_query.transform = _body.global_transform * local
	_query.motion = Vector3.UP * resting_probe_distance
	_query.collision_mask = _body.collision_mask
	_query.exclude = exclude


func _character_collisions(character: CharacterBody3D) -> Array[Dictionary]:
	var out: Array[Dictionary] = []
	var sides: Array[Dictionary] = []
	var reported: Dictionary[String, bool] = {}
	var floor_normal: Vector3 = character.get_floor_normal()
	for i: int in character.get_slide_collision_count():
		var collision: KinematicCollision3D = character.get_slide_collision(i)
		for j: int in collision.get_collision_count():
			var slide: Dictionary = _slide_entry(collision, j)
			if reported.has(slide["key"]):
				continue
			var normal: Vector3 = slide["normal"]
			if character.is_on_floor() and normal.is_equal_approx(floor_normal):
				_floor_entry = slide
			else:
				sides.append(slide)
			reported[slide["key"]] = true
			out.append(slide)
	# As in 2D: pressed into a wall, move_and_slide may report only the wall while the body
	# still stands, and a wall it keeps pressing may go unreported on a frame it moved too
	# little to reach it. Both stay contacts while the body still touches them.
	if not character.is_on_floor():
		_floor_entry = {}
	elif not _floor_entry.is_empty() and not reported.has(_floor_entry["key"]):
		if is_instance_valid(_floor_entry["collider"]):
			out.append(_floor_entry)
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


func _slide_entry(collision: KinematicCollision3D, index: int) -> Dictionary:
	return entry(
		collision.get_collider(index),
		collision.get_collider_rid(index),
		collision.get_collider_shape_index(index),
		collision.get_position(index),
		collision.get_normal(index),
		collision.get_collider_velocity(index)
	)


# The contact [param side] again when the body, moved by its safe margin toward it, touches
# the same shape (or cell); empty once it has moved away.
func _still_touching(character: CharacterBody3D, side: Dictionary) -> Dictionary:
	if not is_instance_valid(side["collider"]):
		return {}
	var normal: Vector3 = side["normal"]
	var collision: KinematicCollision3D = KinematicCollision3D.new()
	var margin: float = character.safe_margin
	if not character.test_move(character.global_transform, -normal * margin, collision, margin):
		return {}
	for j: int in collision.get_collision_count():
		var touched: Dictionary = _slide_entry(collision, j)
		if touched["key"] == side["key"]:
			return touched
	return {}
