class_name DriveTrack
extends RefCounted
## Builds the drive scene's ground in code under a given node: a flat asphalt pad, kerbs of red
## and white ridges ([code]kerb.tres[/code]: a ripple the steering wheel feels), a patch of
## gravel (less grip, a rough feel) and a concrete wall to crash into ([code]hard.tres[/code]).
## Every surface carries its [HapticMaterial] as the [code]haptic_material[/code] metadata
## entry, where [HapticVehicle3D] looks for it.

## The pad's half width, metres: room for a skid-pad circle either side of the start.
const PAD_HALF := 150.0
## The kerbs' height, metres: low enough to roll over without a bump.
const KERB_HEIGHT := 0.03
## Each kerb stripe's length along the kerb, metres (the look; the ripple is the material's).
const STRIPE := 0.6

const KERB := preload("res://addons/haptics/materials/kerb.tres")
const GRAVEL := preload("res://addons/haptics/materials/gravel.tres")
const WALL := preload("res://addons/haptics/materials/hard.tres")

var _parent: Node3D = null


func _init(parent: Node3D) -> void:
	_parent = parent


## The asphalt pad, its top at y = 0.
func pad() -> StaticBody3D:
	var size: Vector3 = Vector3(PAD_HALF * 2.0, 1.0, PAD_HALF * 2.0)
	var body: StaticBody3D = _solid(size, Vector3(0.0, -0.5, 0.0), Color(0.3, 0.31, 0.33))
	body.name = "Pad"
	return body


## A kerb from [param from] to [param to] (x-z corners of its rectangle on the pad), in red
## and white stripes across its longer side.
func kerb(from: Vector2, to: Vector2) -> StaticBody3D:
	var low: Vector2 = Vector2(minf(from.x, to.x), minf(from.y, to.y))
	var high: Vector2 = Vector2(maxf(from.x, to.x), maxf(from.y, to.y))
	var extent: Vector2 = high - low
	var centre: Vector2 = (low + high) * 0.5
	var body: StaticBody3D = StaticBody3D.new()
	body.name = "Kerb"
	body.position = Vector3(centre.x, KERB_HEIGHT * 0.5, centre.y)
	body.add_child(_shape(Vector3(extent.x, KERB_HEIGHT, extent.y)))
	body.set_meta(&"haptic_material", KERB)
	var along_z: bool = extent.y >= extent.x
	var length: float = extent.y if along_z else extent.x
	var stripes: int = maxi(1, roundi(length / STRIPE))
	for i: int in stripes:
		var offset: float = -length * 0.5 + (i + 0.5) * length / stripes
		var size: Vector3 = (
			Vector3(extent.x, KERB_HEIGHT, length / stripes)
			if along_z
			else Vector3(length / stripes, KERB_HEIGHT, extent.y)
		)
		var colour: Color = Color(0.85, 0.12, 0.1) if i % 2 == 0 else Color(0.95, 0.95, 0.95)
		var stripe: MeshInstance3D = _mesh(size, colour)
		stripe.position = Vector3(0.0, 0.0, offset) if along_z else Vector3(offset, 0.0, 0.0)
		body.add_child(stripe)
	_parent.add_child(body)
	return body


## A gravel patch from [param from] to [param to] (x-z corners), flush with the pad.
func gravel(from: Vector2, to: Vector2) -> StaticBody3D:
	var extent: Vector2 = (to - from).abs()
	var centre: Vector2 = (from + to) * 0.5
	var body: StaticBody3D = _solid(
		Vector3(extent.x, 0.02, extent.y), Vector3(centre.x, 0.01, centre.y), Color(0.55, 0.5, 0.4)
	)
	body.name = "Gravel"
	body.set_meta(&"haptic_material", GRAVEL)
	return body


## A concrete wall [param size] (x-z extents; 1.5 m high) centred at [param at] on the pad.
func wall(size: Vector2, at: Vector2) -> StaticBody3D:
	var body: StaticBody3D = _solid(
		Vector3(size.x, 1.5, size.y), Vector3(at.x, 0.75, at.y), Color(0.62, 0.6, 0.56)
	)
	body.name = "Wall"
	body.set_meta(&"haptic_material", WALL)
	return body


## Daylight: a sun with shadows and a pale sky.
func daylight() -> void:
	var sun: DirectionalLight3D = DirectionalLight3D.new()
	sun.rotation_degrees = Vector3(-50.0, -30.0, 0.0)
	sun.shadow_enabled = true
	_parent.add_child(sun)
	var environment: WorldEnvironment = WorldEnvironment.new()
	environment.environment = Environment.new()
	environment.environment.background_mode = Environment.BG_COLOR
	environment.environment.background_color = Color(0.62, 0.75, 0.88)
	environment.environment.ambient_light_source = Environment.AMBIENT_SOURCE_COLOR
	environment.environment.ambient_light_color = Color(0.55, 0.58, 0.62)
	_parent.add_child(environment)


func _solid(size: Vector3, at: Vector3, colour: Color) -> StaticBody3D:
	var body: StaticBody3D = StaticBody3D.new()
	body.position = at
	body.add_child(_shape(size))
	body.add_child(_mesh(size, colour))
	_parent.add_child(body)
	return body


static func _shape(size: Vector3) -> CollisionShape3D:
	var shape: CollisionShape3D = CollisionShape3D.new()
	var box: BoxShape3D = BoxShape3D.new()
	box.size = size
	shape.shape = box
	return shape


static func _mesh(size: Vector3, colour: Color) -> MeshInstance3D:
	var mesh: MeshInstance3D = MeshInstance3D.new()
	var box: BoxMesh = BoxMesh.new()
	box.size = size
	mesh.mesh = box
	var paint: StandardMaterial3D = StandardMaterial3D.new()
	paint.albedo_color = colour
	mesh.material_override = paint
	return mesh
