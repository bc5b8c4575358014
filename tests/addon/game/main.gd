extends Node2D
## The level (a TileMapLayer floor next to a tile wall, built here) and the addon test's
## driver: the device's hand is held to the right, the game's own input actions are fed from
## it, the player runs into the wall. Prints the result and quits with 0 when, on every
## physics frame at the wall, the normal force pushed away from the wall steadily, an impact
## was felt on hitting it and the servo spins what the project set; 1 otherwise.

const TILE := 32
const FLOOR_ROW := 12
const WALL_COLUMN := 16
const FRAMES := 240
const SETTLE_FRAMES := 6
const MIN_PUSH_N := 0.5

var _player: CharacterBody2D = null
var _probe: Node = null
var _frame: int = 0
var _frames_at_wall: int = 0
var _pushes: PackedFloat32Array = []
var _impacts: Array[Vector2] = []


func _ready() -> void:
	add_child(_tiles())
	_player = (load("res://player.tscn") as PackedScene).instantiate()
	_player.position = Vector2(4.5 * TILE, FLOOR_ROW * TILE - 18.0)
	add_child(_player)
	_probe = _player.get_node(^"HapticProbe")
	_probe.connect(&"impact", _on_impact)
	Haptics.hand_follows_input = false
	Haptics.device.set_hand_target(Vector2.RIGHT)


func _physics_process(_delta: float) -> void:
	_frame += 1
	var wall_x: float = WALL_COLUMN * TILE - 10.0
	if absf(_player.position.x - wall_x) < 0.5 and _player.is_on_floor():
		_frames_at_wall += 1
		if _frames_at_wall > SETTLE_FRAMES:
			_pushes.append(-Haptics.get_forces()["normal"].x)
	if _frame >= FRAMES:
		_finish()


func _on_impact(_collider: Object, normal: Vector2, speed: float) -> void:
	print("impact: normal %s, %.2f m/s" % [normal, speed])
	_impacts.append(normal)


func _finish() -> void:
	set_physics_process(false)
	var failures: PackedStringArray = []
	if not Haptics.is_available():
		failures.append("the extension is not loaded")
	if _pushes.size() < 60:
		failures.append("only %d frames at the wall" % _pushes.size())
	var spin_us: float = Haptics.servo.get_stats().get("spin_us", -1.0)
	if spin_us != ProjectSettings.get_setting("haptics/servo/spin_us"):
		failures.append("the servo spins %s us, not the project's haptics/servo/spin_us" % spin_us)
	var weakest: float = INF
	var strongest: float = 0.0
	for push: float in _pushes:
		weakest = minf(weakest, push)
		strongest = maxf(strongest, push)
	if weakest < MIN_PUSH_N:
		failures.append("the wall's push dropped to %.3f N" % weakest)
	if strongest > weakest * 1.2:
		failures.append("the push was not steady: %.3f to %.3f N" % [weakest, strongest])
	if not Vector2.LEFT in _impacts:
		failures.append("no impact on hitting the wall (impacts: %s)" % [_impacts])
	print(
		(
			"addon game: %d frames at the wall, push away from it %.3f-%.3f N, impacts %s"
			% [_pushes.size(), weakest, strongest, _impacts]
		)
	)
	for failure: String in failures:
		printerr("FAIL: " + failure)
	get_tree().quit(1 if not failures.is_empty() else 0)


func _tiles() -> TileMapLayer:
	var tile_set: TileSet = TileSet.new()
	tile_set.tile_size = Vector2i(TILE, TILE)
	tile_set.add_physics_layer()
	var source: TileSetAtlasSource = TileSetAtlasSource.new()
	source.texture_region_size = Vector2i(TILE, TILE)
	var image: Image = Image.create(TILE, TILE, false, Image.FORMAT_RGBA8)
	image.fill(Color(0.4, 0.3, 0.2))
	source.texture = ImageTexture.create_from_image(image)
	tile_set.add_source(source, 0)
	source.create_tile(Vector2i.ZERO)
	var half: float = TILE * 0.5
	var data: TileData = source.get_tile_data(Vector2i.ZERO, 0)
	data.add_collision_polygon(0)
	data.set_collision_polygon_points(
		0,
		0,
		[Vector2(-half, -half), Vector2(half, -half), Vector2(half, half), Vector2(-half, half)]
	)
	var layer: TileMapLayer = TileMapLayer.new()
	layer.tile_set = tile_set
	for column: int in range(0, WALL_COLUMN + 1):
		layer.set_cell(Vector2i(column, FLOOR_ROW), 0, Vector2i.ZERO)
	for row: int in range(FLOOR_ROW - 5, FLOOR_ROW):
		layer.set_cell(Vector2i(WALL_COLUMN, row), 0, Vector2i.ZERO)
	return layer
