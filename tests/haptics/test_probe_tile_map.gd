extends TestSuite
## The probe on a body standing on a [TileMap] (the node every Godot 4.0-4.2 project has,
## its layers in one node): the touched tile's material is read from the layer that holds
## it, as on a [TileMapLayer], and a collider whose tiles the probe cannot read says so once.

const TILE := 32
const FLOOR_ROW := 6
## The soft tile's stiffness and friction, N per unit of hand depth and of hand speed.
const SOFT_K := 0.7
const SOFT_B := 0.2
const DEFAULT_K := 2.0


## A body that falls and stands, as a platformer's does.
class Faller:
	extends CharacterBody2D

	func _physics_process(delta: float) -> void:
		velocity.y += 980.0 * delta
		move_and_slide()


var door: HapticsTestKit.Door = null
var world: Node2D = null
var probe: HapticProbe = null
var soft: HapticMaterial = null


func before_each() -> void:
	door = autofree(HapticsTestKit.manual())
	assert_true(HapticsTestKit.no_ramp(door))
	world = Node2D.new()
	soft = HapticMaterial.new()
	soft.stiffness = SOFT_K
	soft.friction = SOFT_B
	var body: Faller = Faller.new()
	var shape: CollisionShape2D = CollisionShape2D.new()
	var rect: RectangleShape2D = RectangleShape2D.new()
	rect.size = Vector2(20.0, 36.0)
	shape.shape = rect
	body.add_child(shape)
	body.position = Vector2(4.5 * TILE, FLOOR_ROW * TILE - 18.0)
	probe = HapticProbe.new()
	probe.haptics = door
	var fallback: HapticMaterial = HapticMaterial.new()
	fallback.stiffness = DEFAULT_K
	probe.default_material = fallback
	body.add_child(probe)
	world.add_child(body)
	add_child_autofree(world)


# A TileMap of two layers (the floor on the second), its one tile soft by the TileSet's
# custom data.
func _tile_map() -> TileMap:
	var tile_set: TileSet = SquareTileSet.make(TILE, 1)
	var source: TileSetAtlasSource = tile_set.get_source(0) as TileSetAtlasSource
	source.get_tile_data(Vector2i.ZERO, 0).set_custom_data(HapticMaterial.TILE_LAYER, soft)
	var tiles: TileMap = TileMap.new()
	tiles.tile_set = tile_set
	tiles.add_layer(-1)
	for column: int in range(0, 10):
		tiles.set_cell(1, Vector2i(column, FLOOR_ROW), 0, Vector2i.ZERO)
	return tiles


# The floor contact's material after [param frames] physics frames standing still.
func _floor_material(frames: int) -> HapticContactMaterial:
	var found: HapticContactMaterial = null
	for frame: int in frames:
		await get_tree().physics_frame
		HapticsTestKit.run(door, roundi(1000.0 / Engine.physics_ticks_per_second))
		for contact: HapticContact in probe.last_frame.contacts:
			if contact.normal.distance_to(Vector2.UP) < 0.01 and contact.material != null:
				found = contact.material
	return found


func test_a_tile_map_tile_feels_like_its_material() -> void:
	world.add_child(_tile_map())
	var material: HapticContactMaterial = await _floor_material(30)
	assert_not_null(material, "the floor was touched")
	if material != null:
		assert_almost_eq(material.stiffness_n, SOFT_K, 1e-6, "the soft tile's, not the default")
		assert_almost_eq(material.friction_n, SOFT_B, 1e-6)
