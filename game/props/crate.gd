class_name Crate
extends RigidBody2D
## A dynamic crate: stacks, falls, floats or sinks in a [WaterVolume] by [member density],
## lands on the player (who feels its weight through the haptic probe), and knocks with a
## sound and a puff of dust scaled by the impact speed.

## How the crate feels to the touch and how its impacts ring.
@export var haptic_material: HapticMaterial = preload("res://addons/haptics/materials/wood.tres")
## Density relative to water ([member WaterVolume.density] is 1.0 for plain water): below it
## the crate floats, above it the crate sinks.
@export_range(0.05, 10.0, 0.01) var density: float = 0.6
## Impacts slower than this (pixels/second of relative speed) make no sound or dust.
@export var impact_threshold: float = 70.0

## Upward buoyant force on the crate as a fraction of its weight, set each physics tick by
## the [WaterVolume] it floats in (0 in air). Whoever holds the crate up carries the rest
## (the player reads this property by name, whatever the body).
var buoyancy: float = 0.0

var _last_velocity: Vector2 = Vector2.ZERO
var _impact_cooldown: float = 0.0
var _effects: LevelEffects = null


func _ready() -> void:
	contact_monitor = true
	max_contacts_reported = 4
	body_entered.connect(_on_body_entered)
	_effects = get_tree().get_first_node_in_group(&"effects") as LevelEffects


func _physics_process(delta: float) -> void:
	_last_velocity = linear_velocity
	if _impact_cooldown > 0.0:
		_impact_cooldown -= delta


func _on_body_entered(body: Node) -> void:
	if _impact_cooldown > 0.0 or _effects == null:
		return
	var other_velocity: Vector2 = Vector2.ZERO
	if body is RigidBody2D:
		other_velocity = (body as RigidBody2D).linear_velocity
	var speed: float = (_last_velocity - other_velocity).length()
	if speed < impact_threshold:
		return
	if body is Player:
		(body as Player).knock(speed / 400.0)
	_impact_cooldown = 0.12
	_effects.impact(global_position, speed, haptic_material)
