extends RefCounted
## The crashes of a car's chassis, physics tick by physics tick: a collider the chassis starts
## to touch (its reported contacts, [member RigidBody3D.contact_monitor]) is a crash, sized by
## the change of the chassis's velocity over the tick it came in (a crash that stops a car
## from 12 m/s is 12 m/s; a graze changes little), pushed on the hand the way the hit pushed
## the car, in the car's axes as its driver sees them (x right, y up, z back toward the
## driver). A wheel renders that push's x, so the x is never less than half of it: a crash
## straight ahead yanks the wheel toward the side of the car it struck.
## A collider touched again within the release time is the same crash.
## [br][br]
## A touch whose normal lies within [member ground_angle_rad] of up (against gravity) is the
## ground the car drives on, not a crash: the chassis bottoming out on a landing is felt in the
## seat, not through the steering rack. A wall's or another car's side is steeper and still is.

## Below this change of velocity (m/s), a new touch is no crash (a kerb's edge, a scrape).
var min_speed_m_per_s: float = 1.0
## A collider lost for less than this (s) and touched again is the same crash.
var release_s: float = 0.3
## A touch whose normal is within this angle of up (rad) is ground, no crash.
var ground_angle_rad: float = deg_to_rad(45.0)

var _body: RigidBody3D = null
var _velocity_before: Vector3 = Vector3.ZERO
var _have_velocity: bool = false
# Each touched collider's instance id with the physics frame it was last touched on.
var _touching: Dictionary[int, int] = {}


func _init(p_body: RigidBody3D) -> void:
	_body = p_body
	_body.contact_monitor = true
	_body.max_contacts_reported = maxi(_body.max_contacts_reported, 8)


## The crashes that began since the last call (once a physics tick), each a [Dictionary]:
## [code]collider[/code] (Object), [code]speed[/code] (the change of velocity, m/s) and
## [code]push[/code] (unit, the car's axes as its driver sees them).
func crashes() -> Array[Dictionary]:
	var out: Array[Dictionary] = []
	var now: int = Engine.get_physics_frames()
	var velocity: Vector3 = _body.linear_velocity
	var change: float = (velocity - _velocity_before).length() if _have_velocity else 0.0
	_velocity_before = velocity
	_have_velocity = true
	var state: PhysicsDirectBodyState3D = PhysicsServer3D.body_get_direct_state(_body.get_rid())
	if state == null:
		return out
	var up: Vector3 = up_of(state)
	var reported: Dictionary[int, bool] = {}
	for i: int in state.get_contact_count():
		# Ground touches are left out altogether, so a ground and a wall of one body (one
		# collider) still crash on the wall however long the chassis scraped the ground.
		if is_ground(state.get_contact_local_normal(i), up):
			continue
		var collider: Object = state.get_contact_collider_object(i)
		var id: int = state.get_contact_collider_id(i)
		if reported.has(id):
			continue
		reported[id] = true
		var began: bool = not _touching.has(id)
		_touching[id] = now
		if began and change >= min_speed_m_per_s:
			var at: Vector3 = state.get_contact_local_position(i)
			(
				out
				. append(
					{
						"collider": collider,
						"speed": change,
						"push": push_of(state.get_contact_local_normal(i), at),
					}
				)
			)
	var hold: int = ceili(release_s * Engine.physics_ticks_per_second)
	for id: int in _touching.keys():
		if now - _touching[id] > hold:
			_touching.erase(id)
	return out


## Whether a touch along [param normal] (world, from what was touched toward the car) is the
## ground: within [member ground_angle_rad] of [param up].
func is_ground(normal: Vector3, up: Vector3) -> bool:
	return normal.normalized().dot(up) >= cos(ground_angle_rad)


## Up where the car is: against its gravity (an [Area3D] may turn it), world up when it has none.
static func up_of(state: PhysicsDirectBodyState3D) -> Vector3:
	var gravity: Vector3 = state.total_gravity
	return -gravity.normalized() if not gravity.is_zero_approx() else Vector3.UP


## The push of a hit along [param normal] (world, from what was hit toward the car) at
## [param point] (world), in the car's axes as its driver sees them, its x at least half.
func push_of(normal: Vector3, point: Vector3) -> Vector3:
	var chassis: Basis = _body.global_transform.basis.orthonormalized()
	# A VehicleBody3D drives along its +z with its +x on its left.
	var right: Vector3 = -chassis.x
	var back: Vector3 = -chassis.z
	var push: Vector3 = Vector3(normal.dot(right), normal.dot(chassis.y), normal.dot(back))
	if absf(push.x) < 0.5:
		var side: float = (point - _body.global_position).dot(right)
		push.x = 0.5 * (-1.0 if side < 0.0 else 1.0)
		push = Vector3(
			push.x, push.y, signf(push.z) * sqrt(maxf(0.0, 1.0 - 0.25 - push.y * push.y))
		)
	return push.normalized()
