class_name DriveCar
extends VehicleBody3D
## The drive scene's car, built in code: a 1200 kg hatchback on four [VehicleWheel3D]s, front
## wheels steered, rear wheels driven, with a [HapticVehicle3D] that makes its steering felt.
## It steers with the device (its x is the wheel: the arrow keys move the simulated one), or
## with the arrow keys when there is no device to steer with; Up drives, Down brakes and then
## reverses slowly.
## [br][br]
## Its dimensions are a small car's: 2.5 m between the axles, 1.6 m between the wheels,
## wheels 0.31 m in radius, the suspension settling 6 cm under the car's weight (Godot's
## stiffness is per unit of the car's mass: compression = g / (4 × stiffness)).

## The road-wheel angle at full lock, rad (the device's full deflection).
const STEER_LOCK := 0.45
## How fast the keys turn the wheels, rad/s.
const KEY_STEER_SPEED := 1.2
## Front and rear axles' distance from the centre, metres (front is +z).
const AXLE_Z := 1.25
## The wheels' distance from the centre line, metres.
const WHEEL_X := 0.8
const WHEEL_RADIUS := 0.31

## The engine's force at full throttle, N (about 0.35 g).
@export var max_engine_force: float = 4000.0
## Reversing, a share of that force, and a top speed backward (m/s): Down held to stop the
## car must not fling it backward at full force.
@export var reverse_force_share: float = 0.4
@export var max_reverse_speed: float = 4.0
## The brakes' force at full brake (Godot's brake, per wheel).
@export var max_brake: float = 60.0
## Read the arrow keys (off: [member throttle] and, without the device, [member steering] are
## the caller's).
@export var use_keys: bool = true

## -1 (full brake, then reverse) .. 1 (full throttle).
var throttle: float = 0.0
## The steering node (the device's wheel).
var haptics: HapticVehicle3D = null


func _init() -> void:
	mass = 1200.0
	center_of_mass_mode = CENTER_OF_MASS_MODE_CUSTOM
	center_of_mass = Vector3(0.0, 0.25, 0.0)
	var body_shape: CollisionShape3D = CollisionShape3D.new()
	var box: BoxShape3D = BoxShape3D.new()
	box.size = Vector3(1.5, 0.5, 3.9)
	body_shape.shape = box
	body_shape.position = Vector3(0.0, 0.7, 0.0)
	add_child(body_shape)
	add_child(_body_mesh())
	for front: bool in [true, false]:
		for side: float in [1.0, -1.0]:
			add_child(_wheel(front, side))
	haptics = HapticVehicle3D.new()
	haptics.name = "HapticVehicle3D"
	haptics.steer_lock = STEER_LOCK
	add_child(haptics)


func _physics_process(delta: float) -> void:
	if use_keys:
		throttle = Input.get_axis(&"ui_down", &"ui_up")
	var speed: float = linear_velocity.dot(global_basis.z)
	if throttle < 0.0 and speed > 1.0:
		engine_force = 0.0
		brake = -throttle * max_brake
	elif throttle < 0.0:
		var reversing: bool = speed > -max_reverse_speed
		engine_force = throttle * max_engine_force * reverse_force_share if reversing else 0.0
		brake = 0.0
	else:
		engine_force = throttle * max_engine_force
		brake = 0.0
	var by_device: bool = haptics.device_steers()
	if by_device:
		steering = haptics.get_steering_angle()
	elif use_keys:
		var target: float = Input.get_axis(&"ui_right", &"ui_left") * STEER_LOCK
		steering = move_toward(steering, target, KEY_STEER_SPEED * delta)
	haptics.steers_with_device = by_device


## The car's speed along its heading, m/s (negative reversing).
func forward_speed() -> float:
	return linear_velocity.dot(global_basis.z)


func _wheel(front: bool, side: float) -> VehicleWheel3D:
	var wheel: VehicleWheel3D = VehicleWheel3D.new()
	wheel.name = ("Front" if front else "Rear") + ("Left" if side > 0.0 else "Right")
	wheel.position = Vector3(WHEEL_X * side, 0.35, AXLE_Z if front else -AXLE_Z)
	wheel.use_as_steering = front
	wheel.use_as_traction = not front
	wheel.wheel_radius = WHEEL_RADIUS
	wheel.wheel_rest_length = 0.2
	wheel.suspension_travel = 0.15
	wheel.suspension_stiffness = 40.0
	wheel.suspension_max_force = 20000.0
	wheel.damping_compression = 1.5
	wheel.damping_relaxation = 2.0
	wheel.wheel_friction_slip = 1.0
	wheel.wheel_roll_influence = 0.3
	var tyre: MeshInstance3D = MeshInstance3D.new()
	var cylinder: CylinderMesh = CylinderMesh.new()
	cylinder.top_radius = WHEEL_RADIUS
	cylinder.bottom_radius = WHEEL_RADIUS
	cylinder.height = 0.22
	tyre.mesh = cylinder
	tyre.rotation_degrees = Vector3(0.0, 0.0, 90.0)
	tyre.material_override = _paint(Color(0.08, 0.08, 0.09))
	wheel.add_child(tyre)
	return wheel


func _body_mesh() -> Node3D:
	var shell: Node3D = Node3D.new()
	var lower: MeshInstance3D = MeshInstance3D.new()
	var lower_box: BoxMesh = BoxMesh.new()
	lower_box.size = Vector3(1.5, 0.5, 3.9)
	lower.mesh = lower_box
	lower.position = Vector3(0.0, 0.7, 0.0)
	lower.material_override = _paint(Color(0.13, 0.42, 0.78))
	shell.add_child(lower)
	var cabin: MeshInstance3D = MeshInstance3D.new()
	var cabin_box: BoxMesh = BoxMesh.new()
	cabin_box.size = Vector3(1.35, 0.5, 2.0)
	cabin.mesh = cabin_box
	cabin.position = Vector3(0.0, 1.2, -0.3)
	cabin.material_override = _paint(Color(0.7, 0.82, 0.92))
	shell.add_child(cabin)
	return shell


static func _paint(color: Color) -> StandardMaterial3D:
	var paint: StandardMaterial3D = StandardMaterial3D.new()
	paint.albedo_color = color
	return paint
