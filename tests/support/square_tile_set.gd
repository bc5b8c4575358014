class_name SquareTileSet
extends RefCounted
## A TileSet for the probe's tile tests: square tiles, each a full-square collision polygon,
## with the probe's [code]haptic_material[/code] custom data layer (empty).


## [param count] square tiles of [param tile] pixels side by side in one atlas (source 0),
## at atlas coordinates (0, 0), (1, 0), ...
static func make(tile: int, count: int) -> TileSet:
	var tile_set: TileSet = TileSet.new()
	tile_set.tile_size = Vector2i(tile, tile)
	tile_set.add_physics_layer()
	tile_set.add_custom_data_layer()
	tile_set.set_custom_data_layer_name(0, HapticMaterial.TILE_LAYER)
	tile_set.set_custom_data_layer_type(0, TYPE_OBJECT)
	var source: TileSetAtlasSource = TileSetAtlasSource.new()
	source.texture_region_size = Vector2i(tile, tile)
	source.texture = ImageTexture.create_from_image(
		Image.create(tile * count, tile, false, Image.FORMAT_RGBA8)
	)
	tile_set.add_source(source, 0)
	var half: float = tile * 0.5
	var square: PackedVector2Array = [
		Vector2(-half, -half), Vector2(half, -half), Vector2(half, half), Vector2(-half, half)
	]
	for column: int in count:
		source.create_tile(Vector2i(column, 0))
		var data: TileData = source.get_tile_data(Vector2i(column, 0), 0)
		data.add_collision_polygon(0)
		data.set_collision_polygon_points(0, 0, square)
	return tile_set
