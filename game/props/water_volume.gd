@tool
class_name WaterVolume
extends HapticWater
## The game's water: the addon's [HapticWater] (drag and a steady downward force for the
## haptic probe, buoyancy and damping for rigid bodies) plus what the side-scroller adds:
## layout by [member size], the [Player] told when it enters and leaves, each [Crate]'s
## lift kept on the crate, and splashes.
##
## The water is the rectangle of the volume's [RectangleShape2D] collision shape; its top edge
## is the surface. Give [member size] to have the shape (and the drawn water of
## [code]water.tscn[/code]) laid out with its top-left corner at the node's origin; with
## [member size] zero the shape is left as the scene or script made it.
## [br][br]
## Each physics tick every [RigidBody2D] inside is pushed up as [method HapticWater.buoyancy_of]
## says (a crate less dense than the water floats with that fraction submerged, a denser one
## sinks) and [member Crate.buoyancy] shows it. The [Player] is told when it enters and
## leaves ([method Player.enter_water]), and a splash is made where anything crosses the
## surface.

## Width and height of the volume, in pixels, from the node's origin (the top-left corner);
## zero leaves the collision shape alone.
@export var size: Vector2 = Vector2.ZERO:
	set = set_size
## A body crossing the surface faster than this (pixels/second) splashes.
@export var splash_threshold: float = 40.0

var _effects: LevelEffects = null
var _rect: Rect2 = Rect2()


func _ready() -> void:
	_apply_size()
	_rect = _find_rect()
	if Engine.is_editor_hint():
		return
	super()
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


# The lift on a crate is its to show (the player feels a crate's weight less by it).
func _on_lift(body: RigidBody2D, lift: float) -> void:
	if body is Crate:
		(body as Crate).buoyancy = lift


func _on_body_entered(body: Node2D) -> void:
	super(body)
	if body is Player:
		(body as Player).enter_water(self)
		_splash(body, (body as Player).velocity)
	elif body is RigidBody2D:
		_splash(body, (body as RigidBody2D).linear_velocity)


func _on_body_exited(body: Node2D) -> void:
	super(body)
	if body is Player:
		(body as Player).exit_water(self)
		_splash(body, (body as Player).velocity)
	elif body is RigidBody2D:
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
