extends CharacterBody2D
## Runs with left/right, jumps with jump; gravity from the project. Speeds up with
## move_toward as Godot's 2D platformer demo does (also its 120 physics ticks per second and
## strong gravity): pushed into a wall its speed alternates between 0 and one step, and a
## step this small (a slow run-up) leaves move_and_slide not reporting the wall on many
## frames while the player stays against it.

const SPEED := 300.0
const ACCELERATION := SPEED * 1.5
const JUMP_SPEED := 700.0

var gravity: float = ProjectSettings.get_setting("physics/2d/default_gravity", 980.0)


func _physics_process(delta: float) -> void:
	var target: float = Input.get_axis(&"left", &"right") * SPEED
	velocity.x = move_toward(velocity.x, target, ACCELERATION * delta)
	if is_on_floor() and Input.is_action_just_pressed(&"jump"):
		velocity.y = -JUMP_SPEED
	velocity.y += gravity * delta
	move_and_slide()
