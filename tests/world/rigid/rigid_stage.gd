extends Node2D
## The traps of Godot's demo [code]2d/physics_platformer[/code] for a rigid-body player, in one
## stage of our own (nothing downloaded): a floor, a wall to run into, a seesaw plank pinned
## on a pillar, a lift that an [AnimationPlayer] moves down (by position, outside the physics
## step, as the demo's platforms move; the test advances it once a tick, since in the idle
## frame a loaded machine's uneven frames moved it in jumps the player fell onto) and
## enemies that can be dropped on the player's head. The
## player is [code]rigid_player.tscn[/code] with its own [HapticProbe], scaled by the
## addon's rule from the player's gravity.

const PLAYER_SCENE := preload("res://tests/world/rigid/rigid_player.tscn")
const RigidPlayer := preload("res://tests/world/rigid/rigid_player.gd")

## Top of the floor, px.
const FLOOR_Y := 600.0
## Where the player starts on the floor.
const START_X := 300.0
## The wall's face toward the start, px.
const WALL_X := 620.0
## The seesaw's pin (the plank's centre).
const SEESAW := Vector2(1000.0, 574.0)
const PLANK_SIZE := Vector2(128.0, 8.0)
## The demo's plank mass, kg.
const PLANK_MASS := 5.10204
## The lift's centre at the top and bottom of its ride, and how long the ride takes.
const LIFT_TOP := Vector2(1500.0, 440.0)
const LIFT_BOTTOM := Vector2(1500.0, 575.0)
const LIFT_RIDE_S := 3.0
const LIFT_SIZE := Vector2(88.0, 24.0)
## From the player's origin down to the end of its ray (its feet), px.
const FEET_BELOW := 14.0
## From the player's origin up to the top of its head, px.
const HEAD_ABOVE := 12.0
## An enemy: the demo's mass (the default 1 kg) and its three circles.
const ENEMY_MASS := 1.0
const ENEMY_RADIUS := 7.0

var player: RigidPlayer = null
var probe: HapticProbe = null
var plank: RigidBody2D = null
var lift: CharacterBody2D = null

var _lift_animation: AnimationPlayer = null


func _init() -> void:
	_add_static(Rect2(-200.0, FLOOR_Y, 2400.0, 200.0))
	_add_static(Rect2(WALL_X, FLOOR_Y - 200.0, 40.0, 200.0))
	_add_seesaw()
	_add_lift()
	player = PLAYER_SCENE.instantiate() as RigidPlayer
	player.position = Vector2(START_X, FLOOR_Y - FEET_BELOW)
	probe = player.get_node(^"HapticProbe") as HapticProbe
	probe.pixels_per_metre = HapticProbe.pixels_per_metre_for_gravity(RigidPlayer.GRAVITY)
	add_child(player)


## Puts the player standing at [param feet] (the end of its ray), at rest.
func place_player(feet: Vector2) -> void:
	PhysicsServer2D.body_set_state(
		player.get_rid(),
		PhysicsServer2D.BODY_STATE_TRANSFORM,
		Transform2D(0.0, feet - Vector2(0.0, FEET_BELOW))
	)
	PhysicsServer2D.body_set_state(
		player.get_rid(), PhysicsServer2D.BODY_STATE_LINEAR_VELOCITY, Vector2.ZERO
	)


## Drops an enemy from 50 px above the player's head (the demo's "spawn" action).
func spawn_enemy_above() -> RigidBody2D:
	var enemy: RigidBody2D = RigidBody2D.new()
	enemy.mass = ENEMY_MASS
	enemy.lock_rotation = true
	for offset: Vector2 in [Vector2(-0.5, -1.1), Vector2(3.2, 1.6), Vector2(-6.2, 1.8)]:
		var shape: CollisionShape2D = CollisionShape2D.new()
		var circle: CircleShape2D = CircleShape2D.new()
		circle.radius = ENEMY_RADIUS
		shape.shape = circle
		shape.position = offset
		enemy.add_child(shape)
	enemy.position = player.position + 50.0 * Vector2.UP
	add_child(enemy)
	return enemy


## Starts the lift's ride down from [constant LIFT_TOP]; [method advance_lift] moves it.
func start_lift() -> void:
	_lift_animation.play(&"down")


## Moves the lift on by [param delta] seconds of its ride.
func advance_lift(delta: float) -> void:
	_lift_animation.advance(delta)


## Where the player stands on the lift at the top of its ride.
func lift_top_feet() -> Vector2:
	return LIFT_TOP - Vector2(0.0, LIFT_SIZE.y * 0.5)


func _add_static(rect: Rect2) -> StaticBody2D:
	var body: StaticBody2D = StaticBody2D.new()
	body.position = rect.get_center()
	body.add_child(_box(rect.size))
	add_child(body)
	return body


func _box(size: Vector2) -> CollisionShape2D:
	var shape: CollisionShape2D = CollisionShape2D.new()
	var rect: RectangleShape2D = RectangleShape2D.new()
	rect.size = size
	shape.shape = rect
	return shape


# The demo's seesaw: a plank pinned at its centre to a pillar standing on the floor.
func _add_seesaw() -> void:
	var pillar: StaticBody2D = _add_static(
		Rect2(SEESAW.x - 8.0, SEESAW.y - 1.0, 16.0, FLOOR_Y - SEESAW.y + 1.0)
	)
	pillar.name = "Pillar"
	plank = RigidBody2D.new()
	plank.name = "Plank"
	plank.mass = PLANK_MASS
	plank.position = SEESAW
	plank.add_child(_box(PLANK_SIZE))
	add_child(plank)
	var pin: PinJoint2D = PinJoint2D.new()
	pin.position = SEESAW
	pin.node_a = ^"../Plank"
	pin.node_b = ^"../Pillar"
	add_child(pin)


# The demo's moving platform: a CharacterBody2D whose position an AnimationPlayer sets.
func _add_lift() -> void:
	lift = CharacterBody2D.new()
	lift.name = "Lift"
	lift.position = LIFT_TOP
	var polygon: CollisionPolygon2D = CollisionPolygon2D.new()
	var half: Vector2 = LIFT_SIZE * 0.5
	polygon.polygon = PackedVector2Array(
		[Vector2(-half.x, -half.y), Vector2(half.x, -half.y), half, Vector2(-half.x, half.y)]
	)
	lift.add_child(polygon)
	add_child(lift)
	var animation: Animation = Animation.new()
	animation.length = LIFT_RIDE_S
	var track: int = animation.add_track(Animation.TYPE_VALUE)
	animation.track_set_path(track, NodePath("Lift:position"))
	animation.track_set_interpolation_type(track, Animation.INTERPOLATION_CUBIC)
	animation.track_insert_key(track, 0.0, LIFT_TOP)
	animation.track_insert_key(track, LIFT_RIDE_S, LIFT_BOTTOM)
	var library: AnimationLibrary = AnimationLibrary.new()
	library.add_animation(&"down", animation)
	_lift_animation = AnimationPlayer.new()
	_lift_animation.callback_mode_process = AnimationMixer.ANIMATION_CALLBACK_MODE_PROCESS_MANUAL
	_lift_animation.add_animation_library(&"", library)
	add_child(_lift_animation)
