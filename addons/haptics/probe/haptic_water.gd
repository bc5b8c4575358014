@icon("res://addons/haptics/icons/haptic_water.svg")
class_name HapticWater
extends Area2D
## Water for the haptic probe: while the probed body is inside, it feels drag against its
## velocity and a steady downward pull. Rigid bodies inside float or sink by
## [member density] against theirs. Self-contained: it needs nothing from the game but a
## [CollisionShape2D] child (a rectangle: its top edge is the surface).
## [br][br]
## The probe reads any [Area2D] with [code]drag_coefficient[/code] and
## [code]inertia_force[/code] properties as water; this one adds buoyancy. Use the area's
## own [signal Area2D.body_entered] and [signal Area2D.body_exited] for splashes; a script
## that extends this one can override [method _on_lift] to see each body's lift.

## Drag coefficient c in F = −c·v, newtons per metre per second of the body's velocity.
@export_range(0.0, 100.0, 0.01, "suffix:N·s/m") var drag_coefficient: float = 0.8
## Constant force along "down" while inside, newtons (negative: felt as lift).
@export_range(-100.0, 100.0, 0.01, "suffix:N") var inertia_force: float = 0.4
## The water's density relative to a rigid body's ([code]density[/code] property or
## metadata, else 1): a body less dense than the water floats. 0 turns buoyancy off.
@export_range(0.0, 10.0, 0.01) var density: float = 1.0
## Linear and angular damping added to rigid bodies inside, per second.
@export_range(0.0, 20.0, 0.01) var body_damping: float = 2.5

var _floating: Array[RigidBody2D] = []


func _ready() -> void:
	linear_damp_space_override = Area2D.SPACE_OVERRIDE_COMBINE
	linear_damp = body_damping
	angular_damp_space_override = Area2D.SPACE_OVERRIDE_COMBINE
	angular_damp = body_damping
	body_entered.connect(_on_body_entered)
	body_exited.connect(_on_body_exited)


## World-space y of the surface: the top of the first rectangle shape (else the origin).
func get_surface_y() -> float:
	for child: Node in get_children():
		var collision: CollisionShape2D = child as CollisionShape2D
		if collision != null and collision.shape is RectangleShape2D:
			return (collision.global_transform * collision.shape.get_rect()).position.y
	return global_position.y


## Buoyant force on [param body] right now as a fraction of its weight: the submerged
## fraction of its first shape's bounding box × [member density] / the body's density (0 when
## dry, or when [member density] is 0).
func buoyancy_of(body: RigidBody2D) -> float:
	var box: Rect2 = _bounds(body)
	if density <= 0.0 or box.size.y <= 0.0:
		return 0.0
	var submerged: float = clampf((box.end.y - get_surface_y()) / box.size.y, 0.0, 1.0)
	return submerged * density / density_of(body)


func _physics_process(_delta: float) -> void:
	for body: RigidBody2D in _floating:
		if body.freeze:
			continue
		var lift: float = buoyancy_of(body)
		_on_lift(body, lift)
		if lift > 0.0:
			body.apply_central_force(-body.get_gravity() * body.mass * body.gravity_scale * lift)


## Called each physics tick for each unfrozen rigid body inside with its [param lift] (as
## in [method buoyancy_of]), before the force is applied. Does nothing here.
func _on_lift(_body: RigidBody2D, _lift: float) -> void:
	pass


func _on_body_entered(body: Node2D) -> void:
	if body is RigidBody2D:
		_floating.append(body)


func _on_body_exited(body: Node2D) -> void:
	if body is RigidBody2D:
		_floating.erase(body)


static func _bounds(body: RigidBody2D) -> Rect2:
	for child: Node in body.get_children():
		var collision: CollisionShape2D = child as CollisionShape2D
		if collision != null and collision.shape != null:
			return collision.global_transform * collision.shape.get_rect()
	return Rect2()


## The density [param body] declares (a [code]density[/code] property, else metadata), else 1.
static func density_of(body: Object) -> float:
	var declared: Variant = body.get(&"density")
	if declared is float and declared > 0.0:
		return declared
	var meta: Variant = body.get_meta(&"density", 1.0)
	return meta if meta is float and meta > 0.0 else 1.0
