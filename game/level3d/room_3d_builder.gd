class_name Room3DBuilder
extends RefCounted
## Makes the [Room3D]'s parts: boxes with a look and a feel, the pool, crates, the ramp and
## platform, the goal ring, the explorer with its probe, the light, camera and status line.

const FLOOR_SIZE := Vector2(14.0, 12.0)
const WALL_HEIGHT := 1.5
const RAMP_DEGREES := 14.0
const WOOD: HapticMaterial = preload("res://addons/haptics/materials/wood.tres")
const HARD: HapticMaterial = preload("res://addons/haptics/materials/hard.tres")

var _room: Node3D = null


func _init(p_room: Node3D) -> void:
	_room = p_room


## The floor, the four walls, a light and the sky.
func room() -> void:
	var size: Vector2 = FLOOR_SIZE
	box(Vector3(size.x, 1.0, size.y), Vector3(0.0, -0.5, 0.0), Color(0.55, 0.6, 0.5), HARD)
	var half: Vector2 = size / 2.0
	for side: float in [-1.0, 1.0]:
		var along_x: Vector3 = Vector3(size.x, WALL_HEIGHT, 0.4)
		box(along_x, Vector3(0.0, WALL_HEIGHT / 2.0, side * half.y), Color(0.7, 0.65, 0.6), HARD)
		var along_z: Vector3 = Vector3(0.4, WALL_HEIGHT, size.y)
		box(along_z, Vector3(side * half.x, WALL_HEIGHT / 2.0, 0.0), Color(0.7, 0.65, 0.6), HARD)
	var sun: DirectionalLight3D = DirectionalLight3D.new()
	sun.rotation_degrees = Vector3(-55.0, -30.0, 0.0)
	sun.shadow_enabled = true
	_room.add_child(sun)
	var environment: WorldEnvironment = WorldEnvironment.new()
	environment.environment = Environment.new()
	environment.environment.background_mode = Environment.BG_COLOR
	environment.environment.background_color = Color(0.12, 0.16, 0.22)
	environment.environment.ambient_light_source = Environment.AMBIENT_SOURCE_COLOR
	environment.environment.ambient_light_color = Color(0.5, 0.55, 0.6)
	_room.add_child(environment)


## A static box of [param size] at [param at], turned by [param degrees], coloured and felt.
func box(
	size: Vector3,
	at: Vector3,
	color: Color,
	material: HapticMaterial,
	degrees: Vector3 = Vector3.ZERO
) -> StaticBody3D:
	var body: StaticBody3D = StaticBody3D.new()
	body.set_meta(&"haptic_material", material)
	_dress(body, size, color)
	body.position = at
	body.rotation_degrees = degrees
	_room.add_child(body)
	return body


## Water [param size] deep and wide, its bottom on the floor at [param at].
func pool(at: Vector3, size: Vector3) -> HapticWater3D:
	var water: HapticWater3D = HapticWater3D.new()
	water.name = "Pool"
	var shape: CollisionShape3D = CollisionShape3D.new()
	shape.shape = BoxShape3D.new()
	(shape.shape as BoxShape3D).size = size
	water.add_child(shape)
	water.add_child(_mesh(size, Color(0.2, 0.45, 0.85, 0.45)))
	water.position = at + Vector3(0.0, size.y / 2.0, 0.0)
	_room.add_child(water)
	return water


## A wooden crate, 0.6 m, 4 kg, resting at [param at].
func crate(at: Vector3) -> RigidBody3D:
	var body: RigidBody3D = RigidBody3D.new()
	body.mass = 4.0
	body.set_meta(&"haptic_material", WOOD)
	_dress(body, Vector3.ONE * 0.6, Color(0.6, 0.42, 0.22))
	body.position = at
	_room.add_child(body)
	return body


## A platform 1 m high under [param goal], and a ramp up to it from the +z side.
func platform_with_ramp(goal: Vector3) -> void:
	var top: Vector3 = Vector3(goal.x, 0.5, goal.z)
	box(Vector3(3.0, 1.0, 3.0), top, Color(0.5, 0.5, 0.58), HARD)
	var slope: float = deg_to_rad(RAMP_DEGREES)
	var length: float = 1.0 / sin(slope)
	var run: float = length * cos(slope)
	var centre: Vector3 = Vector3(goal.x, 0.5 - 0.1, goal.z + 1.5 + run / 2.0)
	box(
		Vector3(3.0, 0.2, length), centre, Color(0.6, 0.55, 0.45), WOOD, Vector3(RAMP_DEGREES, 0, 0)
	)


## The goal: a gold ring on the platform, an area the explorer walks into.
func goal_ring(at: Vector3) -> Area3D:
	var area: Area3D = Area3D.new()
	area.name = "Goal"
	var shape: CollisionShape3D = CollisionShape3D.new()
	var cylinder: CylinderShape3D = CylinderShape3D.new()
	cylinder.radius = 0.7
	cylinder.height = 1.2
	shape.shape = cylinder
	area.add_child(shape)
	var ring: MeshInstance3D = MeshInstance3D.new()
	var torus: TorusMesh = TorusMesh.new()
	torus.inner_radius = 0.5
	torus.outer_radius = 0.7
	ring.mesh = torus
	ring.material_override = _look(Color(1.0, 0.8, 0.2))
	ring.position = Vector3(0.0, 0.1, 0.0)
	area.add_child(ring)
	area.position = at + Vector3(0.0, 0.6, 0.0)
	_room.add_child(area)
	return area


## The explorer at [param at], with its probe and a body to see.
func explorer(at: Vector3) -> Explorer:
	var body: Explorer = Explorer.new()
	body.name = "Explorer"
	var shape: CollisionShape3D = CollisionShape3D.new()
	var capsule: CapsuleShape3D = CapsuleShape3D.new()
	capsule.radius = 0.3
	capsule.height = 1.0
	shape.shape = capsule
	body.add_child(shape)
	var look: MeshInstance3D = MeshInstance3D.new()
	var mesh: CapsuleMesh = CapsuleMesh.new()
	mesh.radius = 0.3
	mesh.height = 1.0
	look.mesh = mesh
	look.material_override = _look(Color(0.95, 0.45, 0.2))
	body.add_child(look)
	var probe: HapticProbe3D = HapticProbe3D.new()
	probe.name = "HapticProbe3D"
	body.add_child(probe)
	body.position = at
	_room.add_child(body)
	return body


## The camera the room follows the explorer with.
func camera() -> Camera3D:
	var view: Camera3D = Camera3D.new()
	view.current = true
	_room.add_child(view)
	return view


## The line of words at the top of the screen.
func status_label() -> Label:
	return StatusLine.add_to(_room, 20)


func _dress(body: CollisionObject3D, size: Vector3, color: Color) -> void:
	var shape: CollisionShape3D = CollisionShape3D.new()
	shape.shape = BoxShape3D.new()
	(shape.shape as BoxShape3D).size = size
	body.add_child(shape)
	body.add_child(_mesh(size, color))


func _mesh(size: Vector3, color: Color) -> MeshInstance3D:
	var mesh: MeshInstance3D = MeshInstance3D.new()
	var box_mesh: BoxMesh = BoxMesh.new()
	box_mesh.size = size
	mesh.mesh = box_mesh
	mesh.material_override = _look(color)
	return mesh


func _look(color: Color) -> StandardMaterial3D:
	var look: StandardMaterial3D = StandardMaterial3D.new()
	look.albedo_color = color
	if color.a < 1.0:
		look.transparency = BaseMaterial3D.TRANSPARENCY_ALPHA
	return look
