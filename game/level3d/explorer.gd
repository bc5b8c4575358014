class_name Explorer
extends CharacterBody3D
## The 3D level's avatar, driven by acceleration control as the 2D sub is: the input
## vector's ground part sets its acceleration, a low top speed keeps the feel close to
## velocity control, and pushing the stylus up (or the jump action) jumps from a floor.
##
## The vector comes from the keyboard here (the move_* actions, relative to the camera's
## heading), or from whoever sets [member input_vector] with [member use_keyboard] off: a
## [HapticProbe3D] (in world space), an autopilot, a test.

## Upward input beyond this jumps from a floor.
const JUMP_INPUT := 0.6

## Acceleration at full input deflection, m/s².
@export var acceleration: float = 12.0
## Top speed over the ground, m/s.
@export var max_speed: float = 3.0
## Deceleration with no input, m/s².
@export var braking: float = 10.0
## Take-off speed of a jump, m/s.
@export var jump_speed: float = 4.0
## Read the move_* actions (and ui_accept to jump) each tick; turn off to drive
## [member input_vector].
@export var use_keyboard: bool = true
## Force with which it shoves a rigid body it walks into, newtons at full input.
@export var push_force: float = 30.0

## Current input vector, world space, length at most 1.
var input_vector: Vector3 = Vector3.ZERO


func _physics_process(delta: float) -> void:
	if use_keyboard:
		input_vector = _keyboard_vector()
	var ground: Vector3 = Vector3(input_vector.x, 0.0, input_vector.z).limit_length(1.0)
	var flat: Vector3 = Vector3(velocity.x, 0.0, velocity.z)
	if ground.is_zero_approx():
		flat = flat.move_toward(Vector3.ZERO, braking * delta)
	else:
		flat = (flat + ground * acceleration * delta).limit_length(max_speed * ground.length())
	velocity.x = flat.x
	velocity.z = flat.z
	if is_on_floor():
		var jump: bool = use_keyboard and Input.is_action_just_pressed(&"ui_accept")
		if jump or input_vector.y > JUMP_INPUT:
			velocity.y = jump_speed
	else:
		velocity += get_gravity() * delta
	move_and_slide()
	_push_bodies(ground)


# The arrows on the ground, forward being away from the camera.
func _keyboard_vector() -> Vector3:
	var keys: Vector2 = Input.get_vector(&"move_left", &"move_right", &"move_up", &"move_down")
	var heading: Basis = HapticProbe3D.heading(get_viewport().get_camera_3d())
	return heading * Vector3(keys.x, 0.0, keys.y)


func _push_bodies(ground: Vector3) -> void:
	for i: int in get_slide_collision_count():
		var collision: KinematicCollision3D = get_slide_collision(i)
		var rigid: RigidBody3D = collision.get_collider() as RigidBody3D
		var into: float = -collision.get_normal().dot(ground)
		if rigid != null and into > 0.0:
			rigid.apply_central_force(-collision.get_normal() * into * push_force)
