class_name PongPaddleView
extends Node3D
## One player's paddle: a disc facing its normal, in the player's colour, another colour
## while the spin paddle is on, brighter while it touches the ball; held as a gun it is a
## barrel along the normal instead.

const SPIN_COLOR: Color = Color(0.75, 0.35, 1.0)
const THICKNESS_M: float = 0.025
const BARREL_LENGTH_M: float = 0.3

var _color: Color = Color.WHITE
var _disc_material: StandardMaterial3D = StandardMaterial3D.new()
var _disc: MeshInstance3D = MeshInstance3D.new()
var _barrel: MeshInstance3D = MeshInstance3D.new()
var _rim: MeshInstance3D = MeshInstance3D.new()


## Sizes and colours the paddle.
func setup(radius: float, color: Color) -> void:
	_color = color
	var disc: CylinderMesh = CylinderMesh.new()
	disc.top_radius = radius
	disc.bottom_radius = radius
	disc.height = THICKNESS_M
	disc.radial_segments = 40
	_disc_material.transparency = BaseMaterial3D.TRANSPARENCY_ALPHA
	_disc_material.roughness = 0.4
	disc.material = _disc_material
	_disc.mesh = disc
	_disc.name = "Disc"
	add_child(_disc)
	var rim: TorusMesh = TorusMesh.new()
	rim.inner_radius = radius - 0.012
	rim.outer_radius = radius + 0.012
	var rim_material: StandardMaterial3D = StandardMaterial3D.new()
	rim_material.albedo_color = color.lightened(0.3)
	rim_material.emission_enabled = true
	rim_material.emission = color
	rim.material = rim_material
	_rim.mesh = rim
	_rim.name = "Rim"
	add_child(_rim)
	var barrel: CylinderMesh = CylinderMesh.new()
	barrel.top_radius = 0.03
	barrel.bottom_radius = 0.045
	barrel.height = BARREL_LENGTH_M
	var barrel_material: StandardMaterial3D = StandardMaterial3D.new()
	barrel_material.albedo_color = Color(0.2, 0.22, 0.25)
	barrel_material.metallic = 0.6
	barrel.material = barrel_material
	_barrel.mesh = barrel
	_barrel.position = Vector3(0.0, BARREL_LENGTH_M * 0.5, 0.0)
	_barrel.name = "Barrel"
	add_child(_barrel)
	show_modes(false, false, false)


## Places the paddle's centre at [param center], facing [param normal].
func place(center: Vector3, normal: Vector3) -> void:
	var up: Vector3 = normal.normalized() if not normal.is_zero_approx() else Vector3.UP
	var rotation_to: Quaternion = Quaternion(Vector3.UP, up)
	transform = Transform3D(Basis(rotation_to), center)


## Shows the modes: spin paddle, gun, and whether it touches the ball now.
func show_modes(spin: bool, gun: bool, touching: bool) -> void:
	var color: Color = SPIN_COLOR if spin else _color
	_disc_material.albedo_color = Color(color.lightened(0.35 if touching else 0.0), 0.85)
	(_rim.mesh.surface_get_material(0) as StandardMaterial3D).emission = color
	_disc.visible = not gun
	_rim.visible = not gun
	_barrel.visible = gun


## The disc's colour now (the player's, or the spin paddle's).
func get_color() -> Color:
	return _disc_material.albedo_color
