extends RigidBody2D
## A rigid-body platformer player written the way Godot's demo [code]2d/physics_platformer[/code]
## writes its own (Godot 4 version): a custom integrator that sets the velocity itself, a
## floor found from contacts whose normal points up, the floor's own velocity carried, and a
## downward ray as the first collision shape that keeps the body above the floor. Driven
## through [member move] and [member jump] as the demo's script is through its actions.

## Gravity the player falls with, px/s² (the demo's project gravity).
const GRAVITY := 900.0
const WALK_ACCEL := 1000.0
const WALK_DEACCEL := 1000.0
const WALK_MAX_VELOCITY := 200.0
const AIR_ACCEL := 250.0
const AIR_DEACCEL := 250.0
const JUMP_VELOCITY := 380.0
const MAX_FLOOR_AIRBORNE_TIME := 0.15
## A contact normal at least this much up is a floor.
const FLOOR_DOT := 0.6

## Walk: -1 left, 1 right, 0 stand.
var move: float = 0.0
## Jump while held (from the floor).
var jump: bool = false
## Jumps begun so far.
var jumps: int = 0
## Whether the last physics step left the player touching a floor.
var found_floor: bool = false

var _jumping: bool = false
var _airborne_time: float = 1e20
var _floor_h_velocity: float = 0.0


func _integrate_forces(state: PhysicsDirectBodyState2D) -> void:
	var velocity: Vector2 = state.get_linear_velocity()
	var step: float = state.get_step()
	velocity.x -= _floor_h_velocity
	_floor_h_velocity = 0.0
	found_floor = false
	var floor_index: int = -1
	for i: int in state.get_contact_count():
		if state.get_contact_local_normal(i).dot(Vector2.UP) > FLOOR_DOT:
			found_floor = true
			floor_index = i
	_airborne_time = 0.0 if found_floor else _airborne_time + step
	var on_floor: bool = _airborne_time < MAX_FLOOR_AIRBORNE_TIME
	if _jumping and velocity.y > 0.0:
		_jumping = false
	var accel: float = WALK_ACCEL if on_floor else AIR_ACCEL
	var deaccel: float = WALK_DEACCEL if on_floor else AIR_DEACCEL
	if move < 0.0 and velocity.x > -WALK_MAX_VELOCITY:
		velocity.x -= accel * step
	elif move > 0.0 and velocity.x < WALK_MAX_VELOCITY:
		velocity.x += accel * step
	elif move == 0.0:
		velocity.x = move_toward(velocity.x, 0.0, deaccel * step)
	if on_floor and jump and not _jumping:
		velocity.y = -JUMP_VELOCITY
		_jumping = true
		jumps += 1
	if found_floor:
		_floor_h_velocity = state.get_contact_collider_velocity_at_position(floor_index).x
		velocity.x += _floor_h_velocity
	velocity.y += GRAVITY * step
	state.set_linear_velocity(velocity)
