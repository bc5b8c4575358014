class_name Player
extends CharacterBody2D
## The avatar, driven by acceleration control as in the movement-based paper.
##
## The input vector's deviation from centre sets the acceleration; a low top speed keeps
## the feel close to velocity control. The vector comes from the keyboard/gamepad here, or
## from whoever sets [member input_vector] with [member use_keyboard] off (the haptic
## device, an autopilot, a test).

## Emitted on the physics tick when a slide collision begins against a new body.
signal bumped(collider: Object, normal: Vector2, speed: float)

## Acceleration at full input deflection, in pixels per second squared.
@export var acceleration: float = 2400.0
## Top speed, in pixels per second.
@export var max_speed: float = 320.0
## Deceleration with no input, in pixels per second squared.
@export var braking: float = 1600.0
## Read the move_* input actions each tick; turn off to drive [member input_vector].
@export var use_keyboard: bool = true

## Current input vector, each axis in [-1, 1], length at most 1.
var input_vector: Vector2 = Vector2.ZERO

var _touching: Dictionary[int, bool] = {}


func _physics_process(delta: float) -> void:
	if use_keyboard:
		input_vector = Input.get_vector(&"move_left", &"move_right", &"move_up", &"move_down")
	input_vector = input_vector.limit_length(1.0)
	if input_vector.is_zero_approx():
		velocity = velocity.move_toward(Vector2.ZERO, braking * delta)
	else:
		velocity += input_vector * acceleration * delta
		velocity = velocity.limit_length(max_speed)
	var speed_before: float = velocity.length()
	move_and_slide()
	_report_new_contacts(speed_before)


func _report_new_contacts(p_speed: float) -> void:
	var now: Dictionary[int, bool] = {}
	for i: int in get_slide_collision_count():
		var collision: KinematicCollision2D = get_slide_collision(i)
		var id: int = collision.get_collider_id()
		now[id] = true
		if not _touching.has(id):
			bumped.emit(collision.get_collider(), collision.get_normal(), p_speed)
	_touching = now
