class_name PongAvatarView
extends Node3D
## One player's avatar: a body standing on the floor under the workspace centre (the
## origin of this node is the centre), a head, and a faint ring on the floor and one at
## the centre's height showing how far the paddle reaches.

const BODY_HEIGHT_FRACTION: float = 0.7
const SEE_THROUGH_ALPHA: float = 0.4


## Sizes and colours the avatar: [param centre_height] of the workspace centre,
## [param reach] of the paddle, metres. [param see_through]: for the avatar the camera
## stands behind, which would otherwise hide the ball in front of it.
func setup(centre_height: float, reach: float, color: Color, see_through: bool) -> void:
	var body_material: StandardMaterial3D = StandardMaterial3D.new()
	body_material.albedo_color = Color(
		color.darkened(0.2), SEE_THROUGH_ALPHA if see_through else 1.0
	)
	if see_through:
		body_material.transparency = BaseMaterial3D.TRANSPARENCY_ALPHA
	body_material.roughness = 0.6
	var body_height: float = centre_height * BODY_HEIGHT_FRACTION
	var body: CapsuleMesh = CapsuleMesh.new()
	body.radius = PongCourt.AVATAR_BODY_RADIUS_M
	body.height = body_height
	body.material = body_material
	_add(body, Vector3(0.0, body_height * 0.5 - centre_height, 0.0), "Body")
	var head: SphereMesh = SphereMesh.new()
	head.radius = PongCourt.AVATAR_BODY_RADIUS_M * 0.6
	head.height = head.radius * 2.0
	head.material = body_material
	_add(head, Vector3(0.0, body_height - centre_height + head.radius * 0.8, 0.0), "Head")
	var ring_material: StandardMaterial3D = StandardMaterial3D.new()
	ring_material.albedo_color = Color(color, 0.35)
	ring_material.transparency = BaseMaterial3D.TRANSPARENCY_ALPHA
	ring_material.shading_mode = BaseMaterial3D.SHADING_MODE_UNSHADED
	for at: float in [0.0, -centre_height + 0.005]:
		var ring: TorusMesh = TorusMesh.new()
		ring.inner_radius = reach - 0.01
		ring.outer_radius = reach + 0.01
		ring.rings = 48
		ring.material = ring_material
		var instance: MeshInstance3D = _add(ring, Vector3(0.0, at, 0.0), "Reach")
		instance.cast_shadow = GeometryInstance3D.SHADOW_CASTING_SETTING_OFF


func _add(mesh: Mesh, at: Vector3, part_name: String) -> MeshInstance3D:
	var instance: MeshInstance3D = MeshInstance3D.new()
	instance.mesh = mesh
	instance.position = at
	instance.name = part_name
	add_child(instance)
	return instance
