@icon("res://addons/haptics/icons/haptic_material.svg")
class_name HapticMaterial
extends Resource
## How a surface feels: contact stiffness and friction for the continuous force, and the
## shape of the transient played when something hits it.
##
## Assign it to a body by giving the body a [code]haptic_material[/code] property (scripted
## bodies such as crates) or a [code]haptic_material[/code] metadata entry (any body, set
## in the inspector). A [TileMapLayer]'s tiles take theirs from the TileSet's custom data
## layer named [code]haptic_material[/code] (type Object), per tile; an alternative tile
## (flipped, rotated) left without one takes its base tile's. A [GridMap]'s cells take theirs
## by item ([method of_grid_cell]). A body, tile or cell without one but with a
## [PhysicsMaterial] feels like [method from_physics_material] of it; anything else feels
## like the probe's default material.
## [br][br]
## Under a car's wheel ([HapticVehicle3D]) the Road group counts instead: the grip the tyres
## get and the texture the steering wheel feels (a kerb's ripple, a rough surface).

## The custom data layer a TileSet's tiles name their material in.
const TILE_LAYER := &"haptic_material"

## The metadata a [GridMap] names its cells' materials in: a [Dictionary] from a MeshLibrary
## item's name (or its id) to a HapticMaterial.
const GRID_META := &"haptic_materials"
## The largest stiffness, friction and impact gain a material takes.
const MAX_GAIN := HapticFrameLimits.MAX_GAIN
## The largest grip a road surface gives.
const MAX_GRIP := HapticVehicleFacts.MAX_GRIP
## The largest roughness or ripple a road surface has, newtons at the rim.
const MAX_TEXTURE_N := HapticVehicleFacts.MAX_TEXTURE_N

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

@export_group("Road")
## The tyres' friction coefficient on this surface, as a factor on each wheel's own
## ([member VehicleWheel3D.wheel_friction_slip]): 1 dry asphalt, about 0.6 gravel or a wet
## road, 0.1 ice. It changes what the steering feels, not how the car drives: a game whose
## surfaces change the wheels' friction itself leaves this at 1.
@export_range(0.0, MAX_GRIP, 0.01) var grip: float = 1.0
## How rough the surface feels through a steering wheel: the RMS of a noise at the rim, at
## full strength from [member HapticVehicleSettings.roughness_speed_m_per_s] up; 0 smooth.
@export_range(0.0, MAX_TEXTURE_N, 0.01, "suffix:N") var roughness: float = 0.0
## A ripple's amplitude at the rim (a kerb's ridges, a rumble strip); felt only with a
## [member ripple_spacing].
@export_range(0.0, MAX_TEXTURE_N, 0.01, "suffix:N") var ripple: float = 0.0
## The distance between the ripple's ridges: a wheel rolling at v feels it at v / spacing Hz;
## 0, no ripple.
@export_range(0.0, HapticTyreContact.RIPPLE_SPACING_M_MAX, 0.01, "suffix:m")
var ripple_spacing: float = 0.0


# A material saved before 0.3.0 names its friction "damping", which 0.4.0 no longer reads:
# say so instead of loading it with the default friction in silence.
func _set(property: StringName, _value: Variant) -> bool:
	if property == &"damping":
		push_error(
			(
				"HapticMaterial: 'damping' was renamed 'friction' in 0.3.0 and is no longer read; "
				+ "set the material's friction again (docs/upgrading.md)."
			)
		)
	return false


## This material's contact law, as a frame's contact carries it.
func contact_material() -> HapticContactMaterial:
	var out: HapticContactMaterial = HapticContactMaterial.new()
	out.stiffness_n = stiffness
	out.friction_n = friction
	return out


## This material's impact ring, as an impact carries it.
func impact_material() -> HapticImpactMaterial:
	var out: HapticImpactMaterial = HapticImpactMaterial.new()
	out.gain_n_s_per_m = impact_gain
	out.frequency_hz = impact_frequency
	out.decay_s = impact_decay
	return out


## Writes this material's road into [param contact] (a steered wheel's frame entry): its
## grip as a factor on [param wheel_grip], its roughness and ripple.
func write_road(contact: HapticTyreContact, wheel_grip: float) -> void:
	contact.grip = clampf(wheel_grip * grip, 0.0, MAX_GRIP)
	contact.roughness_n = roughness
	contact.ripple_n = ripple if ripple_spacing >= HapticTyreContact.RIPPLE_SPACING_M_MIN else 0.0
	contact.ripple_spacing_m = (
		ripple_spacing if ripple_spacing >= HapticTyreContact.RIPPLE_SPACING_M_MIN else 0.0
	)


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


## The material declared on the node that owns shape [param shape_index] of [param body] (a
## [CollisionShape3D], [CollisionShape2D] or collision polygon: its property or metadata, as
## [method of] reads a body's), or [code]null[/code]. One body may so hold several surfaces,
## as an imported level's ground often does (a road and a verge in one [StaticBody3D]); the
## shape's own material comes before its body's.
static func of_shape(body: Object, shape_index: int) -> HapticMaterial:
	var owner: Object = null
	if body is CollisionObject3D:
		var body_3d: CollisionObject3D = body
		var total: int = 0
		for owner_id: int in body_3d.get_shape_owners():
			total += body_3d.shape_owner_get_shape_count(owner_id)
		if shape_index >= 0 and shape_index < total:
			owner = body_3d.shape_owner_get_owner(body_3d.shape_find_owner(shape_index))
	elif body is CollisionObject2D:
		var body_2d: CollisionObject2D = body
		var total: int = 0
		for owner_id: int in body_2d.get_shape_owners():
			total += body_2d.shape_owner_get_shape_count(owner_id)
		if shape_index >= 0 and shape_index < total:
			owner = body_2d.shape_owner_get_owner(body_2d.shape_find_owner(shape_index))
	return of(owner) if owner != body else null


## The material of the tile at [param cell] of [param tiles]: the TileSet's
## [constant TILE_LAYER] custom data of the tile, else (an alternative tile) of its base
## tile, else the physics material of the first physics layer the tile has a collision
## polygon in (mapped), else [code]null[/code].
static func of_tile(tiles: TileMapLayer, cell: Vector2i) -> HapticMaterial:
	if tiles == null or tiles.tile_set == null:
		return null
	var data: TileData = tiles.get_cell_tile_data(cell)
	if data == null:
		return null
	if tiles.tile_set.has_custom_data_layer_by_name(TILE_LAYER):
		var custom: Variant = data.get_custom_data(TILE_LAYER)
		if custom is HapticMaterial:
			return custom
		# Flipped and rotated alternatives are tiles of their own with their own custom data,
		# most often left empty: they feel like the tile they were made from.
		var source: TileSetAtlasSource = (
			tiles.tile_set.get_source(tiles.get_cell_source_id(cell)) as TileSetAtlasSource
		)
		if source != null and tiles.get_cell_alternative_tile(cell) != 0:
			var base: TileData = source.get_tile_data(tiles.get_cell_atlas_coords(cell), 0)
			custom = base.get_custom_data(TILE_LAYER)
			if custom is HapticMaterial:
				return custom
	for layer: int in tiles.tile_set.get_physics_layers_count():
		var physics: PhysicsMaterial = tiles.tile_set.get_physics_layer_physics_material(layer)
		if physics != null and data.get_collision_polygons_count(layer) > 0:
			return from_physics_material(physics)
	return null


## The material of [param grid]'s cell [param cell]: its item's entry in the grid's
## [constant GRID_META] metadata (by the item's name, else its id), else the grid's physics
## material (mapped), else [code]null[/code].
static func of_grid_cell(grid: GridMap, cell: Vector3i) -> HapticMaterial:
	var item: int = grid.get_cell_item(cell)
	var table: Variant = grid.get_meta(GRID_META, {})
	if item != GridMap.INVALID_CELL_ITEM and table is Dictionary:
		var by_item: Dictionary = table
		var item_name: String = grid.mesh_library.get_item_name(item) if grid.mesh_library else ""
		var found: Variant = by_item.get(item_name, by_item.get(item))
		if found is HapticMaterial:
			return found
	return from_physics_material(grid.physics_material) if grid.physics_material != null else null


## A haptic material standing in for a [PhysicsMaterial] (the one mapping, documented in the
## README): stiffness, impact frequency and decay are the defaults; friction is the default
## friction × the physics friction (1 feels like the default, 0 like ice); the impact gain is
## the default gain × (1 + bounce) (a bouncy surface knocks up to twice as hard).
static func from_physics_material(physics: PhysicsMaterial) -> HapticMaterial:
	var material: HapticMaterial = HapticMaterial.new()
	material.friction = clampf(material.friction * physics.friction, 0.0, MAX_GAIN)
	material.impact_gain = clampf(material.impact_gain * (1.0 + physics.bounce), 0.0, MAX_GAIN)
	return material
