@tool
class_name WaterVolume
extends Area2D
## A body of water: the haptic probe feels drag against the player's velocity and a
## constant downward inertia force while inside; rigid bodies get buoyancy from
## [member density].
##
## The water is the rectangle of the volume's [RectangleShape2D] collision shape; its top edge
## is the surface. Give [member size] to have the shape (and the drawn water of
## [code]water.tscn[/code]) laid out with its top-left corner at the node's origin; with
## [member size] zero the shape is left as the scene or script made it.
## [br][br]
## Each physics tick every [RigidBody2D] inside is pushed up with its weight × the submerged
## fraction of its bounding box × [member density] / the body's density (its
## [code]density[/code] property or metadata, else 1.0), so a body
## less dense than the water floats with that fraction submerged and a denser one sinks;
## [member body_damping] slows bodies inside. The [Player] is told when it enters and
## leaves ([method Player.enter_water]), and a splash is made where anything crosses the
## surface.

## Drag coefficient c in F = −c·v, newtons per metre per second of player velocity.
@export_range(0.0, 100.0, 0.01, "suffix:N·s/m") var drag_coefficient: float = 0.8
## Constant force along "down" while inside, newtons (negative: felt as lift).
@export_range(-100.0, 100.0, 0.01, "suffix:N") var inertia_force: float = 0.4
## Water density relative to the props' densities: a crate with lower density floats.
@export_range(0.0, 10.0, 0.01) var density: float = 1.0
## Width and height of the volume, in pixels, from the node's origin (the top-left corner);
## zero leaves the collision shape alone.
@export var size: Vector2 = Vector2.ZERO:
	set = set_size
## Linear and angular damping added to rigid bodies inside (per second).
@export_range(0.0, 20.0, 0.01) var body_damping: float = 2.5
## A body crossing the surface faster than this (pixels/second) splashes.
@export var splash_threshold: float = 40.0

var _bodies: Array[RigidBody2D] = []
var _shapes: Array[CollisionShape2D] = []
var _gravity: float = 980.0
var _effects: LevelEffects = null
var _rect: Rect2 = Rect2()


func _ready() -> void:
	_apply_size()
	_rect = _find_rect()
	if Engine.is_editor_hint():
		return
	_gravity = ProjectSettings.get_setting("physics/2d/default_gravity", 980.0)
	linear_damp_space_override = Area2D.SPACE_OVERRIDE_COMBINE
	linear_damp = body_damping
	angular_damp_space_override = Area2D.SPACE_OVERRIDE_COMBINE
	angular_damp = body_damping
	body_entered.connect(_on_body_entered)
	body_exited.connect(_on_body_exited)
	_effects = get_tree().get_first_node_in_group(&"effects") as LevelEffects


## Sets [member size] and resizes the collision rectangle and the visuals.
func set_size(value: Vector2) -> void:
	size = value
	if is_node_ready():
		_apply_size()
		_rect = _find_rect()


## World-space rectangle of the water (the volume is assumed not to move).
func get_rect() -> Rect2:
	return _rect


## World-space y of the surface (the top edge).
func get_surface_y() -> float:
	return _rect.position.y


## Buoyant force on [param body] right now as a fraction of its weight (0 when dry).
func buoyancy_of(body: RigidBody2D, shape: CollisionShape2D) -> float:
	if shape == null or shape.shape == null:
		return 0.0
	var box: Rect2 = shape.global_transform * shape.shape.get_rect()
	if box.size.y <= 0.0:
		return 0.0
	var submerged: float = clampf((box.end.y - get_surface_y()) / box.size.y, 0.0, 1.0)
	return submerged * density / _density_of(body)


func _physics_process(_delta: float) -> void:
	if Engine.is_editor_hint():
		return
	for i: int in _bodies.size():
		var body: RigidBody2D = _bodies[i]
		if body.freeze:
			continue
		var lift: float = buoyancy_of(body, _shapes[i])
		if body is Crate:
			(body as Crate).buoyancy = lift
		if lift > 0.0:
			body.apply_central_force(Vector2.UP * body.mass * _gravity * body.gravity_scale * lift)


func _on_body_entered(body: Node2D) -> void:
	if body is Player:
		(body as Player).enter_water(self)
		_splash(body, (body as Player).velocity)
	elif body is RigidBody2D:
		var rigid: RigidBody2D = body
		_bodies.append(rigid)
		_shapes.append(_first_shape(rigid))
		_splash(body, rigid.linear_velocity)


func _on_body_exited(body: Node2D) -> void:
	if body is Player:
		(body as Player).exit_water(self)
		_splash(body, (body as Player).velocity)
	elif body is RigidBody2D:
		var index: int = _bodies.find(body as RigidBody2D)
		if index >= 0:
			_bodies.remove_at(index)
			_shapes.remove_at(index)
		if body is Crate:
			(body as Crate).buoyancy = 0.0
		_splash(body, (body as RigidBody2D).linear_velocity)


func _splash(body: Node2D, velocity: Vector2) -> void:
	if _effects == null or absf(velocity.y) < splash_threshold:
		return
	var surface: float = get_surface_y()
	if absf(body.global_position.y - surface) > 48.0:
		return
	_effects.splash(Vector2(body.global_position.x, surface), absf(velocity.y))


func _find_rect() -> Rect2:
	for child: Node in get_children():
		var collision: CollisionShape2D = child as CollisionShape2D
		if collision != null and collision.shape is RectangleShape2D:
			return collision.global_transform * collision.shape.get_rect()
	return Rect2(global_position, size)


func _apply_size() -> void:
	if size == Vector2.ZERO:
		return
	var collision: CollisionShape2D = get_node_or_null(^"CollisionShape2D") as CollisionShape2D
	if collision != null:
		var rectangle: RectangleShape2D = collision.shape as RectangleShape2D
		if rectangle != null:
			rectangle.size = size
			collision.position = size * 0.5
	var surface: Control = get_node_or_null(^"Water") as Control
	if surface != null:
		surface.position = Vector2(0.0, -10.0)
		surface.size = size + Vector2(0.0, 10.0)
		var shader: ShaderMaterial = surface.material as ShaderMaterial
		if shader != null:
			shader.set_shader_parameter(&"size", surface.size)


static func _first_shape(body: Node) -> CollisionShape2D:
	for child: Node in body.get_children():
		if child is CollisionShape2D:
			return child
	return null


static func _density_of(body: Object) -> float:
	var declared: Variant = body.get(&"density")
	if declared is float and declared > 0.0:
		return declared
	if body.has_meta(&"density"):
		var meta: Variant = body.get_meta(&"density")
		if meta is float and meta > 0.0:
			return meta
	return 1.0
