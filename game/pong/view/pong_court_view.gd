class_name PongCourtView
extends Node3D
## The court drawn from a [PongCourt] (its size comes from the servo's configuration): the
## floor in each player's colour with a grid every [constant GRID_STEP_M] (depth cues),
## the centre line, glass side walls and far wall, the frame of the near wall and the
## ceiling (the camera looks through them), and in beginner mode the targets on the back
## walls (the near one as a frame and a strip on the floor: the camera looks through it).

const GRID_STEP_M: float = 0.5
const FLOOR_COLORS: Array[Color] = [
	Color(0.09, 0.17, 0.28),
	Color(0.27, 0.12, 0.11),
	Color(0.1, 0.24, 0.13),
	Color(0.24, 0.13, 0.27)
]
const LINE_COLOR: Color = Color(0.9, 0.95, 1.0, 0.9)
const GRID_COLOR: Color = Color(0.85, 0.92, 1.0, 0.16)
const GLASS_COLOR: Color = Color(0.55, 0.75, 0.95, 0.1)
const FRAME_COLOR: Color = Color(0.7, 0.85, 1.0, 0.75)
const TARGET_COLOR: Color = Color(1.0, 0.85, 0.25, 0.45)
const TARGET_FRAME_COLOR: Color = Color(1.0, 0.85, 0.25, 1.0)
const TARGET_BAR_M: float = 0.04


## Builds the court (again: children from a previous build are removed). With four
## players, [param viewer] is the player the camera sits behind (its wall is left open).
func build(court: PongCourt, beginner: bool, viewer: int = 0) -> void:
	clear()
	if court.players == 4:
		_build_square(court, beginner, viewer)
		return
	var w: float = court.half_width
	var l: float = court.half_length
	var h: float = court.wall_height
	for player: int in 2:
		var half: MeshInstance3D = _box(
			Vector3(2.0 * w, 0.02, l), FLOOR_COLORS[player], false, "Floor%d" % player
		)
		half.position = Vector3(0.0, -0.01, l * 0.5 * signf(court.back_wall_z(player)))
		add_child(half)
	add_child(_grid(court))
	var centre: MeshInstance3D = _box(Vector3(2.0 * w, 0.004, 0.04), LINE_COLOR, true, "CentreLine")
	centre.position.y = 0.003
	add_child(centre)
	_glass_wall(Vector3(0.02, h, 2.0 * l), Vector3(-w, h * 0.5, 0.0), "LeftWall")
	_glass_wall(Vector3(0.02, h, 2.0 * l), Vector3(w, h * 0.5, 0.0), "RightWall")
	# The camera looks through the viewer's own back wall: glass only on the other's.
	var far_z: float = court.back_wall_z(PongCourt.opponent_of(viewer))
	_glass_wall(Vector3(2.0 * w, h, 0.02), Vector3(0.0, h * 0.5, far_z), "FarWall")
	add_child(_frame(court))
	if beginner:
		for player: int in 2:
			_target(court, player, player == viewer)


## Removes the court.
func clear() -> void:
	for child: Node in get_children():
		remove_child(child)
		child.queue_free()


# A target: the far one filled in on its wall between two posts; the [param near] one (the
# camera looks through its wall) outlined with lines, with a strip on the floor in front of it.
func _target(court: PongCourt, player: int, near: bool) -> void:
	var w: float = court.target_half_width
	var h: float = court.wall_height
	var z: float = court.back_wall_z(player) * 0.995
	var area: MeshInstance3D
	if not near:
		for side: float in [-w, w]:
			var post: MeshInstance3D = _box(
				Vector3(TARGET_BAR_M, h, TARGET_BAR_M), TARGET_FRAME_COLOR, false, "TargetPost"
			)
			post.position = Vector3(side, h * 0.5, z)
			add_child(post)
		area = _box(Vector3(2.0 * w, h, 0.02), TARGET_COLOR, true, "Target%d" % player)
		area.position = Vector3(0.0, h * 0.5, z)
	else:
		var outline: ImmediateMesh = ImmediateMesh.new()
		outline.surface_begin(Mesh.PRIMITIVE_LINE_STRIP, _material(TARGET_FRAME_COLOR, true))
		for corner: Vector2 in [Vector2(-w, 0.0), Vector2(-w, h), Vector2(w, h), Vector2(w, 0.0)]:
			outline.surface_add_vertex(Vector3(corner.x, corner.y, z))
		outline.surface_end()
		add_child(_instance(outline, "TargetOutline%d" % player))
		area = _box(Vector3(2.0 * w, 0.006, 0.3), TARGET_COLOR, true, "Target%d" % player)
		area.position = Vector3(0.0, 0.004, z - 0.15 * signf(z))
	area.cast_shadow = GeometryInstance3D.SHADOW_CASTING_SETTING_OFF
	add_child(area)


# The 4-player court: a floor triangle per player in its colour, the diagonals, glass on
# every wall but the viewer's, and in beginner mode a target on each of those walls.
func _build_square(court: PongCourt, beginner: bool, viewer: int) -> void:
	var l: float = court.half_length
	var h: float = court.wall_height
	for player: int in 4:
		var seat: Basis = PongCourt.side_rotation(player)
		var floor_mesh: ImmediateMesh = ImmediateMesh.new()
		floor_mesh.surface_begin(Mesh.PRIMITIVE_TRIANGLES, _material(FLOOR_COLORS[player], false))
		for corner: Vector3 in [Vector3.ZERO, Vector3(-l, 0.0, l), Vector3(l, 0.0, l)]:
			floor_mesh.surface_set_normal(Vector3.UP)
			floor_mesh.surface_add_vertex(seat * corner)
		floor_mesh.surface_end()
		var triangle: MeshInstance3D = _instance(floor_mesh, "Floor%d" % player)
		(triangle.mesh.surface_get_material(0) as StandardMaterial3D).cull_mode = (
			BaseMaterial3D.CULL_DISABLED
		)
		add_child(triangle)
		if player != viewer:
			var wall: Vector3 = court.back_wall_centre(player)
			var size: Vector3 = (
				Vector3(2.0 * l, h, 0.02) if player < 2 else Vector3(0.02, h, 2.0 * l)
			)
			_glass_wall(size, Vector3(wall.x, h * 0.5, wall.z), "Wall%d" % player)
			if beginner:
				var target_width: float = 2.0 * court.target_half_width
				var target: Vector3 = Vector3(
					minf(size.x, target_width), h, minf(size.z, target_width)
				)
				var area: MeshInstance3D = _box(target, TARGET_COLOR, true, "Target%d" % player)
				area.position = Vector3(wall.x * 0.995, h * 0.5, wall.z * 0.995)
				area.cast_shadow = GeometryInstance3D.SHADOW_CASTING_SETTING_OFF
				add_child(area)
	add_child(_grid(court))
	var diagonals: ImmediateMesh = ImmediateMesh.new()
	diagonals.surface_begin(Mesh.PRIMITIVE_LINES, _material(LINE_COLOR, true))
	for end: Vector3 in [
		Vector3(-l, 0.004, -l), Vector3(l, 0.004, l), Vector3(l, 0.004, -l), Vector3(-l, 0.004, l)
	]:
		diagonals.surface_add_vertex(end)
	diagonals.surface_end()
	add_child(_instance(diagonals, "Diagonals"))
	add_child(_frame(court))


func _glass_wall(size: Vector3, at: Vector3, wall_name: String) -> void:
	var wall: MeshInstance3D = _box(size, GLASS_COLOR, true, wall_name)
	wall.position = at
	wall.cast_shadow = GeometryInstance3D.SHADOW_CASTING_SETTING_OFF
	add_child(wall)


func _grid(court: PongCourt) -> MeshInstance3D:
	var mesh: ImmediateMesh = ImmediateMesh.new()
	mesh.surface_begin(Mesh.PRIMITIVE_LINES, _material(GRID_COLOR, true))
	var w: float = court.half_width
	var l: float = court.half_length
	var x: float = -w
	while x <= w + 1e-4:
		mesh.surface_add_vertex(Vector3(x, 0.002, -l))
		mesh.surface_add_vertex(Vector3(x, 0.002, l))
		x += GRID_STEP_M
	var z: float = -l
	while z <= l + 1e-4:
		mesh.surface_add_vertex(Vector3(-w, 0.002, z))
		mesh.surface_add_vertex(Vector3(w, 0.002, z))
		z += GRID_STEP_M
	mesh.surface_end()
	return _instance(mesh, "Grid")


# The edges of the box the court is: floor rim, wall tops, the near wall's and ceiling's
# outline, the corner posts.
func _frame(court: PongCourt) -> MeshInstance3D:
	var w: float = court.half_width
	var l: float = court.half_length
	var h: float = court.wall_height
	var mesh: ImmediateMesh = ImmediateMesh.new()
	mesh.surface_begin(Mesh.PRIMITIVE_LINES, _material(FRAME_COLOR, true))
	for y: float in [0.003, h]:
		var corners: Array[Vector3] = [
			Vector3(-w, y, -l), Vector3(w, y, -l), Vector3(w, y, l), Vector3(-w, y, l)
		]
		for i: int in 4:
			mesh.surface_add_vertex(corners[i])
			mesh.surface_add_vertex(corners[(i + 1) % 4])
	for corner: Vector2 in [Vector2(-w, -l), Vector2(w, -l), Vector2(w, l), Vector2(-w, l)]:
		mesh.surface_add_vertex(Vector3(corner.x, 0.0, corner.y))
		mesh.surface_add_vertex(Vector3(corner.x, h, corner.y))
	for side: float in [-w, w]:
		mesh.surface_add_vertex(Vector3(side, 0.003, 0.0))
		mesh.surface_add_vertex(Vector3(side, h, 0.0))
	mesh.surface_end()
	return _instance(mesh, "Frame")


func _box(size: Vector3, color: Color, transparent: bool, box_name: String) -> MeshInstance3D:
	var box: BoxMesh = BoxMesh.new()
	box.size = size
	box.material = _material(color, transparent)
	return _instance(box, box_name)


func _instance(mesh: Mesh, instance_name: String) -> MeshInstance3D:
	var instance: MeshInstance3D = MeshInstance3D.new()
	instance.name = instance_name
	instance.mesh = mesh
	return instance


static func _material(color: Color, transparent: bool) -> StandardMaterial3D:
	var material: StandardMaterial3D = StandardMaterial3D.new()
	material.albedo_color = color
	if transparent:
		material.transparency = BaseMaterial3D.TRANSPARENCY_ALPHA
		material.shading_mode = BaseMaterial3D.SHADING_MODE_UNSHADED
		material.cull_mode = BaseMaterial3D.CULL_DISABLED
	else:
		material.roughness = 0.85
	return material
