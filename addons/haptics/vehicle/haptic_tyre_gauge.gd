extends RefCounted
## One steered [VehicleWheel3D] measured as the vehicle renderer takes it
## ([HapticTyreContact]): the load its suspension carries, the slip angle of its contact, its
## speed over the ground and the surface under it. Made by [HapticVehicle3D] before the car's
## first physics tick: the wheel's position then is where Godot attaches its suspension.
##
## The load is the suspension's force as [VehicleBody3D] computes it (Godot 4.6,
## scene/3d/physics/vehicle_body_3d.cpp): the spring, stiffness × compression, and the damper,
## damping × the compression's speed, both per unit of the car's mass, times the mass;
## never negative, at most [member VehicleWheel3D.suspension_max_force]. (Godot after 4.6
## gives that force itself, VehicleWheel3D.get_contact_normal_force(); 4.6 does not.)

## Slip angles are measured only above this contact speed (m/s); slower, the wheel rolls
## straight (the servo fades the torque out below its low_speed_m_per_s anyway).
const MIN_SPEED_M_PER_S := 0.05

## The wheel measured.
var wheel: VehicleWheel3D = null

var _hard_point: Vector3 = Vector3.ZERO  # Where the suspension attaches, chassis axes.
var _down: Vector3 = Vector3.DOWN  # The suspension's direction, chassis axes.


func _init(p_wheel: VehicleWheel3D) -> void:
	wheel = p_wheel
	_hard_point = p_wheel.position
	_down = -p_wheel.basis.y.normalized()


## The suspension's force on the ground, newtons (the game's), 0 in the air.
func load_n(body: VehicleBody3D) -> float:
	if not wheel.is_in_contact():
		return 0.0
	var chassis: Transform3D = body.global_transform
	var down: Vector3 = (chassis.basis * _down).normalized()
	var normal: Vector3 = wheel.get_contact_normal()
	var contact: Vector3 = wheel.get_contact_point()
	var spring: float = wheel.suspension_stiffness * (wheel.wheel_rest_length - length(body))
	var facing: float = normal.dot(down)
	var inverse: float = 10.0 if facing >= -0.1 else -1.0 / facing
	var velocity: Vector3 = (
		body.linear_velocity + body.angular_velocity.cross(contact - chassis.origin)
	)
	var closing: float = normal.dot(velocity) * (inverse if facing < -0.1 else 0.0)
	var damping: float = wheel.damping_compression if closing < 0.0 else wheel.damping_relaxation
	var force: float = (spring * inverse - damping * closing) * body.mass
	return clampf(force, 0.0, wheel.suspension_max_force)


## The suspension's length now, metres, from where the wheel's ray met the ground (the wheel's
## own transform may be an interpolated one). Godot 4.6 casts the ray from a radius above the
## hard point, rest length + two radii long, and scales the hit's fraction of it by rest
## length + one radius: the length is (rest + r)(d + r) / (rest + 2 r) - r, d the contact's
## depth below the hard point, within the suspension's travel. Standing still, the four
## loads of a 1200 kg car measured so added up to its weight within 0.3 %.
func length(body: VehicleBody3D) -> float:
	var chassis: Transform3D = body.global_transform
	var down: Vector3 = (chassis.basis * _down).normalized()
	var depth: float = (wheel.get_contact_point() - chassis * _hard_point).dot(down)
	var radius: float = wheel.wheel_radius
	var rest: float = wheel.wheel_rest_length
	var ray_length: float = rest + 2.0 * radius
	var hit: float = (rest + radius) * (depth + radius) / ray_length if ray_length > 0.0 else rest
	var travel: float = wheel.suspension_travel
	return clampf(hit - radius, rest - travel, rest + travel)


## This tick's [HapticTyreContact] for [param body]'s wheel, with the road of
## [param surface] (null: grip 1, no texture), its slip angle measured against
## [param steer_angle] (the frame's delta: the wheel's own steering may differ).
func measure(body: VehicleBody3D, surface: HapticMaterial, steer_angle: float) -> HapticTyreContact:
	var contact: HapticTyreContact = HapticTyreContact.new()
	contact.in_contact = wheel.is_in_contact()
	if not contact.in_contact:
		return contact
	contact.load_n = minf(load_n(body), HapticVehicleFacts.MAX_TYRE_LOAD_N)
	var chassis: Basis = body.global_transform.basis
	var up: Vector3 = wheel.get_contact_normal().normalized()
	# The wheel's heading as Godot steers it: the chassis's forward turned about its up.
	var heading: Vector3 = (chassis.z.rotated(chassis.y.normalized(), wheel.steering)).normalized()
	heading = (heading - up * heading.dot(up)).normalized()
	var left: Vector3 = up.cross(heading)
	var point: Vector3 = wheel.get_contact_point()
	var velocity: Vector3 = (
		body.linear_velocity + body.angular_velocity.cross(point - body.global_position)
	)
	var along: float = velocity.dot(heading)
	var across: float = velocity.dot(left)
	contact.speed_m_per_s = minf(
		Vector2(along, across).length(), HapticFrameLimits.MAX_SPEED_M_PER_S
	)
	contact.rolling_backward = along < 0.0
	var slip: float = 0.0
	if contact.speed_m_per_s > MIN_SPEED_M_PER_S:
		# Positive when the contact moves to the right of the way the wheel rolls.
		slip = atan2(-across, along) if along >= 0.0 else atan2(across, -along)
	# The frame carries one steering angle: the servo takes this wheel's velocity direction as
	# steer_angle - slip, so a wheel steered otherwise is measured against it.
	slip += steer_angle - wheel.steering
	var limit: float = HapticVehicleFacts.MAX_SLIP_ANGLE_RAD
	contact.slip_angle_rad = clampf(wrapf(slip, -PI, PI), -limit, limit)
	if surface != null:
		surface.write_road(contact, wheel.wheel_friction_slip)
	else:
		contact.grip = clampf(wheel.wheel_friction_slip, 0.0, HapticVehicleFacts.MAX_GRIP)
	return contact
