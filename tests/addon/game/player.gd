extends CharacterBody2D
## Runs with left/right, jumps with jump; gravity from the project.

const SPEED := 220.0
const JUMP_SPEED := 420.0

var gravity: float = ProjectSettings.get_setting("physics/2d/default_gravity", 980.0)


func _physics_process(delta: float) -> void:
	velocity.x = Input.get_axis(&"left", &"right") * SPEED
	if is_on_floor() and Input.is_action_just_pressed(&"jump"):
		velocity.y = -JUMP_SPEED
	velocity.y += gravity * delta
	move_and_slide()
