@icon("res://addons/haptics/icons/haptic_water.svg")
class_name HapticWater3D
extends Area3D
## Water for [HapticProbe3D], as [HapticWater] is for the 2D probe: while the probed body is
## inside, it feels drag against its velocity and a steady downward pull. Rigid bodies inside
## float or sink by [member density] against theirs. It needs nothing from the game but a
## [CollisionShape3D] child (a box: its top face is the surface).

## Drag coefficient c in F = −c·v, newtons per metre per second of the body's velocity.
@export_range(0.0, 100.0, 0.01, "suffix:N·s/m") var drag_coefficient: float = 0.8
## Constant force along "down" while inside, newtons (negative: felt as lift).
@export_range(-100.0, 100.0, 0.01, "suffix:N") var inertia_force: float = 0.4
## The water's density relative to a rigid body's ([code]density[/code] property or
## metadata, else 1): a body less dense than the water floats. 0 turns buoyancy off.
@export_range(0.0, 10.0, 0.01) var density: float = 1.0
## Linear and angular damping added to rigid bodies inside, per second.
@export_range(0.0, 20.0, 0.01) var body_damping: float = 2.5

var _floating: Array[RigidBody3D] = []


func _ready() -> void:
	linear_damp_space_override = Area3D.SPACE_OVERRIDE_COMBINE
	linear_damp = body_damping
	angular_damp_space_override = Area3D.SPACE_OVERRIDE_COMBINE
	angular_damp = body_damping
	body_entered.connect(_on_body_entered)
	body_exited.connect(_on_body_exited)


## World-space height of the surface: the top of the first box shape (else the origin).
func get_surface_y() -> float:
	for child: Node in get_children():
		var collision: CollisionShape3D = child as CollisionShape3D
		if collision != null and collision.shape is BoxShape3D:
			var box: BoxShape3D = collision.shape
			return (collision.global_transform * Vector3(0.0, box.size.y / 2.0, 0.0)).y
	return global_position.y


## Buoyant force on [param body] right now as a fraction of its weight: the submerged
## fraction of its shapes' height × [member density] / the body's density (0 when dry).
func buoyancy_of(body: RigidBody3D) -> float:
	var box: AABB = _bounds(body)
	if density <= 0.0 or box.size.y <= 0.0:
		return 0.0
	var submerged: float = clampf((get_surface_y() - box.position.y) / box.size.y, 0.0, 1.0)
	return submerged * density / HapticWater.density_of(body)


func _physics_process(_delta: float) -> void:
	for body: RigidBody3D in _floating:
		if body.freeze:
			continue
		var lift: float = buoyancy_of(body)
		if lift > 0.0:
			body.apply_central_force(-body.get_gravity() * body.mass * body.gravity_scale * lift)


func _on_body_entered(body: Node3D) -> void:
	if body is RigidBody3D:
		_floating.append(body)


func _on_body_exited(body: Node3D) -> void:
	if body is RigidBody3D:
		_floating.erase(body)


# The world-space box around [param body]'s first collision shape (its mesh's bounds).
static func _bounds(body: RigidBody3D) -> AABB:
	for child: Node in body.get_children():
		var collision: CollisionShape3D = child as CollisionShape3D
		if collision != null and collision.shape != null:
			return collision.global_transform * collision.shape.get_debug_mesh().get_aabb()
	return AABB()
