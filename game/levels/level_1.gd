class_name Level1
extends Level
## Level 1, "Sea Cave": a coastal cave several screens wide. The sub starts on a beach,
## dives under a rock curtain into a flooded cave mouth, climbs into a crate hall above a
## low tunnel, crosses a crystal ridge, dives again through a second pool and surfaces in
## a lagoon where a beacon buoy marks the goal. Pearls lie along the way.
##
## The scene is laid out by [code]tools/gen_level_1.py[/code]; this script wires it: the
## camera follows the player inside [member world_rect], pearls report
## [signal Level.item_collected], the buoy [signal Level.goal_reached], and bumps make dust
## and sound.

## The playable world: the camera never shows anything outside it.
@export var world_rect: Rect2 = Rect2(0.0, 0.0, 8960.0, 1440.0)

## Pearls collected so far.
var collected: int = 0
## Pearls in the level.
var total: int = 0

@onready var _effects: LevelEffects = $Effects as LevelEffects
@onready var _pearls: Node = $Pearls
@onready var _goal: Goal = $Goal as Goal


func _ready() -> void:
	player.global_position = get_spawn_position()
	player.reset_physics_interpolation()
	var camera: Camera2D = player.get_node_or_null(^"Camera2D") as Camera2D
	if camera != null:
		camera.limit_left = int(world_rect.position.x)
		camera.limit_top = int(world_rect.position.y)
		camera.limit_right = int(world_rect.end.x)
		camera.limit_bottom = int(world_rect.end.y)
		camera.enabled = true
		camera.make_current()
		camera.reset_smoothing()
	for child: Node in _pearls.get_children():
		var pearl: Pearl = child as Pearl
		if pearl != null:
			total += 1
			pearl.collected.connect(_on_pearl_collected)
	_goal.reached.connect(reach_goal)
	if DisplayServer.get_name() != "headless":
		($Ambience as AudioStreamPlayer).play()
	player_bumped.connect(_on_bump)


## The number of pearls in the level.
func get_item_total() -> int:
	return total


func _on_pearl_collected(_pearl: Pearl) -> void:
	collected += 1
	report_item_collected(collected, total)


func _on_bump(collider: Object, normal: Vector2, speed: float) -> void:
	var along_normal: float = minf(speed, maxf(0.0, -player.velocity_before_slide.dot(normal)))
	player.knock(along_normal / 400.0)
	var where: Vector2 = player.global_position - normal * Player.RADIUS
	_effects.impact(where, along_normal, HapticMaterial.of(collider))
