class_name Player
extends CharacterBody2D
## The avatar, a small amphibious sub driven by acceleration control as in the
## movement-based paper.
##
## The input vector's deviation from centre sets the acceleration; a low top speed keeps
## the feel close to velocity control. The vector comes from the keyboard/gamepad here, or
## from whoever sets [member input_vector] with [member use_keyboard] off (the haptic
## device, an autopilot, a test).
## [br][br]
## The sub holds up what lands on it (it feels the weight, and sags very slowly under it),
## pushes crates it drives into, and is slowed by water ([method enter_water]). Blocked by a
## wall it keeps no velocity into it, so input turned away moves it off at once.
## The hull pitches toward its motion and faces where it goes; its propeller spins with the
## thrust and bubbles stream from it under water. The collision shape stays a circle, so contact
## normals never depend on the pose.

## Emitted on the physics tick when a slide collision begins against a new body.
signal bumped(collider: Object, normal: Vector2, speed: float)

## Largest pitch of the hull toward its motion, in radians.
const MAX_PITCH: float = 0.8
## Radius of the collision circle, in pixels.
const RADIUS: float = 18.0
## Passes over the slide contacts that drop the velocity into walls: two settle a corner
## of two walls.
const CONTACT_PASSES: int = 2

## Acceleration at full input deflection, in pixels per second squared.
@export var acceleration: float = 2400.0
## Top speed, in pixels per second.
@export var max_speed: float = 320.0
## Deceleration with no input, in pixels per second squared.
@export var braking: float = 1600.0
## Read the move_* input actions each tick; turn off to drive [member input_vector].
@export var use_keyboard: bool = true
## Force with which the sub shoves a dynamic body it drives into, in mass·pixels/s² at full
## input (a 2 kg crate on the floor starts moving from about a third of it).
@export var push_force: float = 3000.0
## Fraction of its own weight the sub holds up for a body lying on it; the rest presses the
## sub down very slowly, so the load stays in contact (and is felt) without drifting off.
@export_range(0.0, 1.0, 0.01) var load_support: float = 0.97
## Top speed in water as a fraction of [member max_speed].
@export_range(0.1, 1.0, 0.01) var water_speed_factor: float = 0.7
## Speed at which the idle sub sinks in water (the paper's downward water inertia), px/s.
@export var water_sink_speed: float = 14.0

## Current input vector, each axis in [-1, 1], length at most 1.
var input_vector: Vector2 = Vector2.ZERO
## Whether the sub is inside at least one [WaterVolume].
var in_water: bool = false
## Velocity of the last physics tick before collisions were resolved (pixels/second): its
## component against a contact normal is how hard that contact was hit.
var velocity_before_slide: Vector2 = Vector2.ZERO
## 1 or -1: the way the hull faces.
var facing: float = 1.0

var _touching: Dictionary[int, bool] = {}
var _now_touching: Dictionary[int, bool] = {}
var _water_count: int = 0
var _gravity: float = 980.0
var _pitch: float = 0.0
var _flip: float = 1.0
var _squash: float = 0.0
var _time: float = 0.0
var _propeller_phase: float = 0.0

@onready var _visual: Node2D = get_node_or_null(^"Visual") as Node2D
@onready var _propeller: Node2D = get_node_or_null(^"Visual/Propeller") as Node2D
@onready var _bubbles: GPUParticles2D = get_node_or_null(^"Bubbles") as GPUParticles2D
@onready var _bubble_material: ParticleProcessMaterial = (
	_bubbles.process_material as ParticleProcessMaterial if _bubbles != null else null
)
@onready var _hum: AudioStreamPlayer2D = get_node_or_null(^"Hum") as AudioStreamPlayer2D


func _ready() -> void:
	_gravity = ProjectSettings.get_setting("physics/2d/default_gravity", 980.0)
	if _visual != null:
		# Posed every rendered frame from the interpolated body: no interpolation of its own.
		_visual.physics_interpolation_mode = Node.PHYSICS_INTERPOLATION_MODE_OFF
	_apply_water_look()
	# No sound without a display (headless runs and tests): nothing to hear, less to leak.
	if _hum != null and DisplayServer.get_name() != "headless":
		_hum.play()


## Called by a [WaterVolume] when the sub enters it.
func enter_water(_volume: Node) -> void:
	_water_count += 1
	if not in_water:
		in_water = true
		_apply_water_look()


## Called by a [WaterVolume] when the sub leaves it.
func exit_water(_volume: Node) -> void:
	_water_count = maxi(0, _water_count - 1)
	if in_water and _water_count == 0:
		in_water = false
		_apply_water_look()


## Squashes the hull briefly, as after a knock of [param strength] in [0, 1].
func knock(strength: float) -> void:
	_squash = maxf(_squash, clampf(strength, 0.0, 1.0))


func _physics_process(delta: float) -> void:
	if use_keyboard:
		input_vector = Input.get_vector(&"move_left", &"move_right", &"move_up", &"move_down")
	input_vector = input_vector.limit_length(1.0)
	var top_speed: float = max_speed * (water_speed_factor if in_water else 1.0)
	if input_vector.is_zero_approx():
		var rest: Vector2 = Vector2(0.0, water_sink_speed) if in_water else Vector2.ZERO
		velocity = velocity.move_toward(rest, braking * delta)
	else:
		velocity += input_vector * acceleration * delta
		velocity = velocity.limit_length(top_speed)
	velocity_before_slide = velocity
	var speed_before: float = velocity.length()
	move_and_slide()
	_stop_into_contacts()
	_report_new_contacts(speed_before)
	_act_on_bodies(delta)


func _process(delta: float) -> void:
	if _visual == null:
		return
	_time += delta
	var speed_fraction: float = clampf(velocity.length() / max_speed, 0.0, 1.0)
	# Face the way of travel (input first, so the hull turns before it moves), with some
	# hysteresis so a vertical climb does not flicker.
	var lead: float = input_vector.x if absf(input_vector.x) > 0.2 else velocity.x / max_speed
	if absf(lead) > 0.15:
		facing = signf(lead)
	_flip = move_toward(_flip, facing, delta * 7.0)
	var target_pitch: float = 0.0
	if speed_fraction > 0.05:
		target_pitch = atan2(velocity.y, absf(velocity.x) + 1.0)
		target_pitch = clampf(target_pitch, -MAX_PITCH, MAX_PITCH) * minf(1.0, speed_fraction * 2.0)
	_pitch = lerpf(_pitch, target_pitch, 1.0 - exp(-8.0 * delta))
	_squash = move_toward(_squash, 0.0, delta * 4.0)
	var bob: float = sin(_time * 2.3) * 1.5 * (1.0 - speed_fraction)
	var squash: float = _squash * _squash * 0.25
	_visual.position = Vector2(0.0, bob)
	_visual.rotation = _pitch * facing
	_visual.scale = Vector2(_flip * (1.0 + squash), 1.0 - squash)
	var thrust: float = input_vector.length()
	if _propeller != null:
		_propeller_phase += delta * (6.0 + 40.0 * thrust)
		_propeller.scale.y = 0.25 + 0.75 * absf(sin(_propeller_phase))
	if _bubbles != null:
		_bubbles.emitting = thrust > 0.1
		_bubbles.amount_ratio = 0.35 + 0.65 * thrust
		_bubbles.position = Vector2(-24.0 * facing * cos(_pitch), -24.0 * sin(_pitch))
		if _bubble_material != null:
			_bubble_material.direction = Vector3(-input_vector.x, -input_vector.y, 0.0)
	if _hum != null:
		_hum.pitch_scale = 0.8 + 0.5 * speed_fraction
		_hum.volume_db = linear_to_db(0.05 + 0.25 * thrust)


# A floating CharacterBody2D's move_and_slide keeps the velocity it was given: pressed into
# a wall the sub kept its full speed into it while not moving, and needed several ticks of
# input the other way before it left (the haptic model kept rendering a wall the hand had
# already turned away from, for 7 ticks). The velocity into a blocking surface is dropped
# instead, down to how fast that surface itself retreats (a moving platform). Dynamic
# bodies are left out: the sub shoves and carries them ([method _act_on_bodies]) with the
# velocity it drives into them. Two passes settle a corner whose second surface re-adds a
# component into the first.
func _stop_into_contacts() -> void:
	var count: int = get_slide_collision_count()
	for _pass: int in CONTACT_PASSES:
		for i: int in count:
			var collision: KinematicCollision2D = get_slide_collision(i)
			var body: RigidBody2D = collision.get_collider() as RigidBody2D
			if body != null and not body.freeze:
				continue
			var normal: Vector2 = collision.get_normal()
			var retreat: float = minf(0.0, collision.get_collider_velocity().dot(normal))
			var into: float = velocity.dot(normal)
			if into < retreat:
				velocity += normal * (retreat - into)


func _report_new_contacts(speed: float) -> void:
	_now_touching.clear()
	for i: int in get_slide_collision_count():
		var collision: KinematicCollision2D = get_slide_collision(i)
		var id: int = collision.get_collider_id()
		if _now_touching.has(id):
			continue  # another shape of a body already reported this tick
		_now_touching[id] = true
		if not _touching.has(id):
			bumped.emit(collision.get_collider(), collision.get_normal(), speed)
	# Swap the two dictionaries instead of allocating a new one each tick.
	var previous: Dictionary[int, bool] = _touching
	_touching = _now_touching
	_now_touching = previous


## Holds up bodies lying on the sub and shoves bodies it drives into.
func _act_on_bodies(delta: float) -> void:
	for i: int in get_slide_collision_count():
		var collision: KinematicCollision2D = get_slide_collision(i)
		var body: RigidBody2D = collision.get_collider() as RigidBody2D
		if body == null or body.freeze:
			continue
		var n: Vector2 = collision.get_normal()
		var push: float = input_vector.dot(-n)
		if push > 0.0:
			body.apply_force(
				-n * push_force * push, collision.get_position() - body.global_position
			)
		if n.y > 0.0:
			# The body lies on the sub: carry the share of its weight that water does not,
			# and cancel its approach so it comes to rest on the hull.
			# A floating body (a crate in water) says how much of its weight water holds up.
			var lift: float = 0.0
			if &"buoyancy" in body:
				lift = body.get(&"buoyancy")
			var weight: float = body.mass * _gravity * body.gravity_scale * maxf(0.0, 1.0 - lift)
			var approach: float = maxf(0.0, (body.linear_velocity - velocity).dot(n))
			body.apply_central_force(
				Vector2.UP * weight * load_support * n.y - n * body.mass * approach / delta
			)


func _apply_water_look() -> void:
	if _visual != null:
		# The sub is drawn over the water so it stays readable; a cool tint says it is wet.
		_visual.modulate = Color(0.78, 0.9, 1.0) if in_water else Color.WHITE
	if _bubble_material == null:
		return
	if in_water:
		_bubble_material.gravity = Vector3(0.0, -60.0, 0.0)
		_bubble_material.color = Color(0.85, 0.95, 1.0, 0.8)
		_bubbles.lifetime = 1.2
	else:
		_bubble_material.gravity = Vector3(0.0, -10.0, 0.0)
		_bubble_material.color = Color(1.0, 1.0, 1.0, 0.35)
		_bubbles.lifetime = 0.45
