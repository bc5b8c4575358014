extends Node2D
## The level (a TileMapLayer floor next to a tile wall, built here) and the addon test's
## driver: the device's hand is held to the right, the game's own input actions are fed from
## it, the player runs into the wall and pushes; then the hand goes left and the player walks
## away. Prints the result and quits with 0 when, on every physics frame after the first
## touch while pushing, the normal force pushed away from the wall steadily, an impact was
## felt on hitting it, the wall stopped being a contact once the player had left it, and
## the servo spins what the project set; 1 otherwise.

const TILE := 32
const FLOOR_ROW := 12
const WALL_COLUMN := 16
const PUSH_FRAMES := 480
const AWAY_FRAMES := 60
## Frames for the smoothed force to settle after the first touch.
const SETTLE_FRAMES := 12
const MIN_PUSH_N := 0.5
const STEADY_RATIO := 1.2
## Farther from the wall than this, in pixels, it must no longer be a contact.
const LEFT_WALL_PX := 0.5

var _player: CharacterBody2D = null
var _half_width: float = 0.0
var _probe: Node = null
var _frame: int = 0
var _touched_at: int = -1
var _pushes: PackedFloat32Array = []
var _impacts: Array[Vector2] = []
# Frames after walking away on which the wall, though left, was still a contact.
var _stuck: PackedStringArray = []
var _away_frames: int = 0


func _ready() -> void:
	add_child(_tiles())
	_player = (load("res://player.tscn") as PackedScene).instantiate()
	_player.position = Vector2(4.5 * TILE, FLOOR_ROW * TILE - 18.0)
	add_child(_player)
	var body: RectangleShape2D = (_player.get_node(^"CollisionShape2D") as CollisionShape2D).shape
	_half_width = body.size.x * 0.5
	_probe = _player.get_node(^"HapticProbe")
	_probe.connect(&"impact", _on_impact)
	Haptics.hand_follows_input = false
	Haptics.device.set_hand_target(Vector2.RIGHT)


# Runs before the player moves: the probe's last frame and the player's position are both
# those of the previous physics frame.
func _physics_process(_delta: float) -> void:
	_frame += 1
	var wall_contact: bool = _touches_wall()
	if _frame <= PUSH_FRAMES:
		if _touched_at < 0 and wall_contact:
			_touched_at = _frame
		if _touched_at >= 0 and _frame > _touched_at + SETTLE_FRAMES:
			_pushes.append(-Haptics.get_forces().parts[HapticMovementFacts.MovementForce.NORMAL].x)
		if _frame == PUSH_FRAMES:
			Haptics.device.set_hand_target(Vector2.LEFT)
		return
	var gap: float = WALL_COLUMN * TILE - (_player.position.x + _half_width)
	if gap > LEFT_WALL_PX:
		_away_frames += 1
		if wall_contact:
			_stuck.append("%.2f px" % gap)
	if _frame >= PUSH_FRAMES + AWAY_FRAMES:
		_finish()


func _on_impact(_collider: Object, normal: Vector2, speed: float) -> void:
	print("impact: normal %s, %.2f m/s" % [normal, speed])
	_impacts.append(normal)


func _touches_wall() -> bool:
	var frame: HapticFrame = _probe.get(&"last_frame")
	for contact: HapticContact in frame.contacts:
		if contact.normal.is_equal_approx(Vector2.LEFT):
			return true
	return false


func _finish() -> void:
	set_physics_process(false)
	var failures: PackedStringArray = []
	if not Haptics.is_available():
		failures.append("the extension is not loaded")
	if _pushes.size() < 120:
		failures.append("only %d frames pushing the wall" % _pushes.size())
	var spin_us: float = Haptics.servo.get_stats().spin_s * 1e6
	if spin_us != ProjectSettings.get_setting("haptics/servo/spin_us"):
		failures.append("the servo spins %s us, not the project's haptics/servo/spin_us" % spin_us)
	var weakest: float = INF
	var strongest: float = 0.0
	var dropped: int = 0
	for push: float in _pushes:
		weakest = minf(weakest, push)
		strongest = maxf(strongest, push)
		dropped += 1 if push < MIN_PUSH_N else 0
	if weakest < MIN_PUSH_N:
		failures.append(
			(
				"the wall's push dropped to %.3f N on %d of %d frames"
				% [weakest, dropped, _pushes.size()]
			)
		)
	if strongest > weakest * STEADY_RATIO:
		failures.append("the push was not steady: %.3f to %.3f N" % [weakest, strongest])
	if not Vector2.LEFT in _impacts:
		failures.append("no impact on hitting the wall (impacts: %s)" % [_impacts])
	if _away_frames < AWAY_FRAMES / 2:
		failures.append("the player did not walk away (%d frames away)" % _away_frames)
	if not _stuck.is_empty():
		failures.append("the wall stayed a contact after leaving it, at gaps %s" % [_stuck])
	print(
		(
			(
				"addon game: %d frames pushing the wall, push away from it %.3f-%.3f N, impacts %s; "
				% [_pushes.size(), weakest, strongest, _impacts]
			)
			+ "walked away %d frames, wall kept at %d of them" % [_away_frames, _stuck.size()]
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
