class_name Stage3D
extends Node3D
## A 3D physics stage for probe tests, built in code: a floor 20 m square at y = 0, and
## makers for what the tests put on it (walls, ramps, ceilings, crates, water, a moving
## platform), and the two body kinds a [HapticProbe3D] serves, each with its probe, pointed
## at a door of the test's own.

## Radius of the test bodies' spheres, metres.
const RADIUS := 0.3


func _init() -> void:
	box(Vector3(20.0, 1.0, 20.0), Vector3(0.0, -0.5, 0.0))


## A static box of [param size] centred at [param at], turned by [param degrees] (Euler, XYZ).
func box(size: Vector3, at: Vector3, degrees: Vector3 = Vector3.ZERO) -> StaticBody3D:
	var body: StaticBody3D = StaticBody3D.new()
	body.add_child(_shape_of(size))
	body.position = at
	body.rotation_degrees = degrees
	add_child(body)
	return body


## A crate of [param mass_kg] and edge [param edge] (a rigid box) at [param at].
func crate(mass_kg: float, edge: float, at: Vector3) -> RigidBody3D:
	var body: RigidBody3D = RigidBody3D.new()
	body.mass = mass_kg
	body.add_child(_shape_of(Vector3.ONE * edge))
	body.position = at
	add_child(body)
	return body


## Water filling [param size] centred at [param at].
func water(size: Vector3, at: Vector3) -> HapticWater3D:
	var area: HapticWater3D = HapticWater3D.new()
	var shape: CollisionShape3D = CollisionShape3D.new()
	var box_shape: BoxShape3D = BoxShape3D.new()
	box_shape.size = size
	shape.shape = box_shape
	area.add_child(shape)
	area.position = at
	add_child(area)
	return area


## A platform (an animatable body) 2 m square at [param at]; move it with its position.
func platform(at: Vector3) -> AnimatableBody3D:
	var body: AnimatableBody3D = AnimatableBody3D.new()
	body.add_child(_shape_of(Vector3(2.0, 0.2, 2.0)))
	body.position = at
	add_child(body)
	return body


## An [Explorer] (a CharacterBody3D, keyboard off) with a probe on [param door], at [param at]:
## a sphere, or with [param capsule] a capsule 1 m tall, as most 3D games' players are.
func walker(door: HapticsTestKit.Door, at: Vector3, capsule: bool = false) -> Explorer:
	var body: Explorer = Explorer.new()
	body.use_keyboard = false
	if capsule:
		var shape: CollisionShape3D = CollisionShape3D.new()
		shape.shape = CapsuleShape3D.new()
		(shape.shape as CapsuleShape3D).radius = RADIUS
		(shape.shape as CapsuleShape3D).height = 1.0
		body.add_child(shape)
	else:
		_sphere_on(body)
	body.position = at
	_probe_on(body, door)
	add_child(body)
	return body


## A rolling ball (a RigidBody3D pushed by its input vector) with a probe on [param door].
func roller(door: HapticsTestKit.Door, at: Vector3) -> Roller3D:
	var body: Roller3D = Roller3D.new()
	_sphere_on(body)
	body.position = at
	_probe_on(body, door)
	add_child(body)
	return body


## The probe of a body made here.
static func probe_of(body: PhysicsBody3D) -> HapticProbe3D:
	return body.get_node(^"HapticProbe3D") as HapticProbe3D


static func _shape_of(size: Vector3) -> CollisionShape3D:
	var shape: CollisionShape3D = CollisionShape3D.new()
	var box_shape: BoxShape3D = BoxShape3D.new()
	box_shape.size = size
	shape.shape = box_shape
	return shape


static func _sphere_on(body: PhysicsBody3D) -> void:
	var shape: CollisionShape3D = CollisionShape3D.new()
	var sphere: SphereShape3D = SphereShape3D.new()
	sphere.radius = RADIUS
	shape.shape = sphere
	body.add_child(shape)


static func _probe_on(body: PhysicsBody3D, door: HapticsTestKit.Door) -> void:
	var probe: HapticProbe3D = HapticProbe3D.new()
	probe.name = "HapticProbe3D"
	probe.haptics = door
	var material: HapticMaterial = HapticMaterial.new()
	material.stiffness = 2.0
	material.friction = 1.0
	probe.default_material = material
	body.add_child(probe)
