class_name Roller3D
extends RigidBody3D
## A ball for probe tests: a rigid body its input vector pushes (acceleration control by
## force), as a game's rolling player would be.

## Force at full input, newtons.
@export var push_force: float = 20.0

## The input vector, world space (a [HapticProbe3D] sets it).
var input_vector: Vector3 = Vector3.ZERO


func _physics_process(_delta: float) -> void:
	apply_central_force(Vector3(input_vector.x, 0.0, input_vector.z) * push_force)
