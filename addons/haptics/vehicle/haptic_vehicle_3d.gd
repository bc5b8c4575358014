@icon("res://addons/haptics/icons/haptic_probe.svg")
class_name HapticVehicle3D
extends Node
## A car's steering on a wheel device: add this node as a child of a [VehicleBody3D] and the
## driver feels its steered tyres, the road and its crashes.
##
## It switches the servo to the vehicle renderer ([HapticsVehicle]) and, each physics tick,
## measures every [VehicleWheel3D] with [member VehicleWheel3D.use_as_steering] (the load its
## suspension carries, the slip angle of its contact, its speed, the [HapticMaterial] of what
## it rolls on: its grip, roughness and ripple) and sends them as a [HapticVehicleFrame]. The
## servo turns them at 1 kHz into the tyres' aligning torque at the rim, which returns the
## wheel toward the way the car goes and goes light as the front lets go, plus the road's
## texture. A collider the chassis starts to touch rings an impact sized by the change of
## velocity, unless the touch comes from below (the ground, as when the car bottoms out on a
## landing: [member crash_ground_angle]).
## [br][br]
## The game steers with [method get_steering_angle] (or [method get_steering] times its own
## steer limit, which must then be [member steer_lock]):
## [codeblock]
## steering = $HapticVehicle3D.get_steering_angle()
## [/codeblock]
## The device's x is the wheel: a wheel's one axis, a stick's or a stylus's left-right.
## docs/vehicle.md in the project has the model and its limits.

## Emitted after each frame is sent, with the frame as sent.
signal frame_sent(frame: HapticVehicleFrame)
## Emitted for each crash played: what the chassis hit and the change of velocity (m/s).
signal crashed(collider: Object, speed: float)

const Haptics := preload("res://addons/haptics/door/haptics.gd")
const HapticsLookup := preload("res://addons/haptics/door/haptics_lookup.gd")
const HapticTyreGauge := preload("res://addons/haptics/vehicle/haptic_tyre_gauge.gd")
const HapticCrashGauge := preload("res://addons/haptics/vehicle/haptic_crash_gauge.gd")
## How far either side of a wheel's contact point its shape is looked for (m).
const SHAPE_RAY_M := 0.05

## The road-wheel angle the device's full deflection steers (rad): the steer limit the game's
## steering is at with the wheel turned all the way.
@export_range(
	HapticVehicleFrame.STEER_LOCK_RAD_MIN,
	HapticVehicleFrame.STEER_LOCK_RAD_MAX,
	0.01,
	"radians_as_degrees"
)
var steer_lock: float = 0.5
## The game steers with the device ([method get_steering_angle]): the servo then moves the
## tyres' slip with the wheel at every tick. Off for a game steered by keys or a pilot.
@export var steers_with_device: bool = true
## Make the vehicle renderer the servo's when this node is ready, and give the previous one
## back when it leaves the tree. It also turns the servo's input dead zone off meanwhile
## ([member HapticInputSettings.dead_zone]): a steering wheel's centre has no play, and a dead
## band there would steer nothing for the first degrees.
@export var take_renderer: bool = true
## The road under a wheel whose ground declares no [HapticMaterial] (on the touched collision
## shape's node, else on the body; a [CSGShape3D] or [GridMap] ground has none to give); null:
## grip 1, smooth.
@export var default_surface: HapticMaterial = null
## How a crash rings when what the chassis hit declares no [HapticMaterial]; null: the servo's
## default impact.
@export var crash_material: HapticMaterial = null
## A new touch of the chassis changing its velocity less than this is no crash.
@export_range(0.0, 20.0, 0.1, "suffix:m/s") var crash_min_speed: float = 1.0
## A collider lost for less than this and touched again is the same crash.
@export_range(0.0, 2.0, 0.01, "suffix:s") var crash_release_s: float = 0.3
## A touch of the chassis whose normal lies within this angle of up is the ground it drives on
## (bottoming out on a landing), felt in the seat, not through the steering: no crash. A wall,
## or another car's side, is steeper.
@export_range(0.0, 90.0, 1.0, "radians_as_degrees") var crash_ground_angle: float = deg_to_rad(45.0)

## The door this node talks to: the [code]Haptics[/code] autoload unless set before it enters
## the tree.
var haptics: Haptics = null
## The last frame sent (for HUDs and tests).
var last_frame: HapticVehicleFrame = HapticVehicleFrame.new()
## Frames sent so far.
var frames_sent: int = 0
## Crashes played so far.
var crashes_played: int = 0

var _body: VehicleBody3D = null
var _renderer: HapticsVehicle = null
var _gauges: Array[HapticTyreGauge] = []
var _crashes: HapticCrashGauge = null
var _previous_mode: StringName = &""
var _previous_dead_zone: float = -1.0
var _ray: PhysicsRayQueryParameters3D = PhysicsRayQueryParameters3D.new()


func _ready() -> void:
	_body = get_parent() as VehicleBody3D
	if _body == null:
		push_error("HapticVehicle3D must be a child of a VehicleBody3D.")
		set_physics_process(false)
		return
	if haptics == null:
		haptics = HapticsLookup.autoload_for(self, "HapticVehicle3D")
	if haptics == null:
		set_physics_process(false)
		return
	for child: Node in _body.get_children():
		var wheel: VehicleWheel3D = child as VehicleWheel3D
		if wheel != null and wheel.use_as_steering:
			_gauges.append(HapticTyreGauge.new(wheel))
	if _gauges.is_empty():
		push_warning("HapticVehicle3D: %s has no VehicleWheel3D with use_as_steering." % _body.name)
	if _gauges.size() > HapticVehicleFacts.VEHICLE_MAX_STEERED_WHEELS:
		push_warning(
			(
				"HapticVehicle3D: %s steers %d wheels; the first %d are felt."
				% [_body.name, _gauges.size(), HapticVehicleFacts.VEHICLE_MAX_STEERED_WHEELS]
			)
		)
		_gauges.resize(HapticVehicleFacts.VEHICLE_MAX_STEERED_WHEELS)
	_crashes = HapticCrashGauge.new(_body)
	_ray.exclude = [_body.get_rid()]  # The shape under a wheel is never the car's own.
	_renderer = HapticsVehicle.of(haptics)
	if take_renderer and _renderer.is_available():
		_previous_mode = haptics.get_render_mode()
		_renderer.activate()
		_previous_dead_zone = _set_dead_zone(0.0)


func _exit_tree() -> void:
	if _renderer != null and _previous_mode != &"" and _renderer.is_active():
		haptics.set_render_mode(_previous_mode)
		_previous_mode = &""
	if _previous_dead_zone >= 0.0:
		_set_dead_zone(_previous_dead_zone)
		_previous_dead_zone = -1.0


# Sets the servo's input dead zone; returns the one it had.
func _set_dead_zone(dead_zone: float) -> float:
	var settings: HapticServoSettings = haptics.servo.get_settings()
	var before: float = settings.input.dead_zone
	settings.input.dead_zone = dead_zone
	haptics.servo.apply_settings(settings)
	return before


func _physics_process(_delta: float) -> void:
	send()
	_play_crashes()


## The device's steering, -1..1, as [member VehicleBody3D.steering] turns: positive left
## (the device turned left); 0 without a device.
func get_steering() -> float:
	if haptics == null:
		return 0.0
	return -clampf(haptics.get_input_vector().x, -1.0, 1.0)


## Whether a game that steers with the device should now: the door has the library and is in
## device control (the player's choice, [member Haptics.control_mode]).
func device_steers() -> bool:
	return (
		haptics != null
		and haptics.is_available()
		and haptics.control_mode == Haptics.CONTROL_DEVICE
		and not haptics.device.is_lost()
	)


## The road-wheel angle the device steers (rad): [method get_steering] × [member steer_lock],
## for [member VehicleBody3D.steering].
func get_steering_angle() -> float:
	return get_steering() * steer_lock


## The vehicle renderer this node drives (its state: [method HapticsVehicle.get_state]).
func renderer() -> HapticsVehicle:
	return _renderer


## Measures the steered wheels and sends this tick's frame.
func send() -> void:
	var frame: HapticVehicleFrame = build_frame()
	_renderer.send_frame(frame)
	last_frame = frame
	frames_sent += 1
	frame_sent.emit(frame)


## This tick's frame: every steered wheel's load, slip, speed and road.
func build_frame() -> HapticVehicleFrame:
	var frame: HapticVehicleFrame = HapticVehicleFrame.new()
	var limit: float = HapticVehicleFacts.MAX_STEER_ANGLE_RAD
	var steer: float = _gauges[0].wheel.steering if not _gauges.is_empty() else _body.steering
	frame.steer_angle_rad = clampf(steer, -limit, limit)
	frame.steer_lock_rad = clampf(steer_lock, HapticVehicleFrame.STEER_LOCK_RAD_MIN, limit)
	frame.steered_by_device = steers_with_device
	frame.reference_load_n = reference_load_n()
	var wheels: Array[HapticTyreContact] = []
	for gauge: HapticTyreGauge in _gauges:
		wheels.append(gauge.measure(_body, _surface_under(gauge.wheel), frame.steer_angle_rad))
	frame.wheels = wheels
	return frame


## The load on one wheel of the car standing still: its weight over its wheel count (the
## steered axle's peak torque at this load is felt as the settings' peak_force_n).
func reference_load_n() -> float:
	var wheel_count: int = 0
	for child: Node in _body.get_children():
		wheel_count += 1 if child is VehicleWheel3D else 0
	var gravity: float = ProjectSettings.get_setting("physics/3d/default_gravity", 9.8)
	var weight: float = _body.mass * gravity * _body.gravity_scale / maxi(wheel_count, 1)
	return clampf(
		weight, HapticVehicleFrame.REFERENCE_LOAD_N_MIN, HapticVehicleFacts.MAX_TYRE_LOAD_N
	)


# The touched shape's material, else its body's, else default_surface.
func _surface_under(wheel: VehicleWheel3D) -> HapticMaterial:
	var ground: Node3D = wheel.get_contact_body()
	var found: HapticMaterial = HapticMaterial.of_shape(ground, _shape_under(wheel, ground))
	if found == null:
		found = HapticMaterial.of(ground)
	return found if found != null else default_surface


# The index of ground's shape under wheel: VehicleWheel3D names only the body, so a body of
# several shapes (an imported level's road and verge) is asked again along the wheel's ray.
func _shape_under(wheel: VehicleWheel3D, ground: Node3D) -> int:
	var body: CollisionObject3D = ground as CollisionObject3D
	if body == null or body.get_shape_owners().size() < 2:
		return 0 if body != null else -1
	var point: Vector3 = wheel.get_contact_point()
	var normal: Vector3 = wheel.get_contact_normal()
	_ray.from = point + normal * SHAPE_RAY_M
	_ray.to = point - normal * SHAPE_RAY_M
	_ray.collision_mask = _body.collision_mask
	var hit: Dictionary = _body.get_world_3d().direct_space_state.intersect_ray(_ray)
	return hit["shape"] if hit.get("collider") == ground else -1


func _play_crashes() -> void:
	_crashes.min_speed_m_per_s = crash_min_speed
	_crashes.release_s = crash_release_s
	_crashes.ground_angle_rad = crash_ground_angle
	for crash: Dictionary in _crashes.crashes():
		var collider: Object = crash["collider"]
		var material: HapticMaterial = HapticMaterial.of(collider)
		var ring: HapticMaterial = material if material != null else crash_material
		var speed: float = minf(crash["speed"], HapticFrameLimits.MAX_SPEED_M_PER_S)
		haptics.push_impact_3d(HapticProbe3D.impact_event(crash["push"], speed, ring))
		crashes_played += 1
		crashed.emit(collider, speed)
