extends TestSuite
## The 3D probe's mapping and surfaces: vectors reach the device in the camera's heading (a
## wall in front of a turned camera still pushes back toward the player), a GridMap cell feels
## like its item's material, a shape's own material wins over its body's, a PhysicsMaterial
## stands in for a missing haptic one, a rigid player driven by the README's line rolls the
## way the camera faces, and [method HapticProbe3D.hit] plays a world-space hit in view axes.

## Runs scenes for seconds: make check (--quick) leaves it out.
const SLOW := true

const TICKS_PER_FRAME := 17
const NORMAL := HapticMovementFacts.MovementForce.NORMAL

var door: HapticsTestKit.Door = null
var stage: Stage3D = null


func before_each() -> void:
	door = autofree(HapticsTestKit.manual())
	assert_true(HapticsTestKit.no_ramp(door) and HapticsTestKit.no_dead_zone(door))
	stage = Stage3D.new()
	add_child_autofree(stage)


func _run_frames(count: int) -> void:
	for i: int in count:
		await get_tree().physics_frame
		HapticsTestKit.run(door, TICKS_PER_FRAME)


func test_a_turned_camera_turns_the_world_into_the_players_view() -> void:
	# The camera looks along -x (turned 90° left): a wall on the world's -x side is in front.
	var camera: Camera3D = Camera3D.new()
	camera.rotation_degrees = Vector3(-30.0, 90.0, 0.0)
	camera.position = Vector3(4.0, 3.0, 0.0)
	stage.add_child(camera)
	camera.make_current()
	stage.box(Vector3(0.5, 2.0, 6.0), Vector3(-2.25, 1.0, 0.0))
	var walker: Explorer = stage.walker(door, Vector3(0.0, Stage3D.RADIUS, 0.0))
	var probe: HapticProbe3D = Stage3D.probe_of(walker)
	assert_almost_eq(probe.view_basis().z, Vector3.RIGHT, 1e-5, "back is the world's +x")
	assert_true(door.device.set_hand_target_3d(Vector3(0.0, 0.0, -0.05)))  # Forward.
	await _run_frames(120)
	assert_almost_eq(walker.position.x, -2.0 + Stage3D.RADIUS, 0.05, "walked to the wall ahead")
	var normals: Array[Vector3] = []
	for contact: HapticContact3D in probe.last_frame.contacts:
		normals.append(contact.normal)
	assert_true(normals.any(func(n: Vector3) -> bool: return n.distance_to(Vector3.BACK) < 0.02))
	assert_gt(door.get_forces_3d().parts[NORMAL].z, 0.8, "pushed back toward the player")


func test_a_rigid_player_rolls_away_from_a_turned_camera_as_the_readme_pushes_it() -> void:
	# The README's line for a RigidBody3D ([Roller3D]):
	# apply_central_force(Vector3(input_vector.x, 0.0, input_vector.z) * push_n) in
	# _physics_process. The camera looks along -x; the stylus pushed forward and lifted.
	var camera: Camera3D = Camera3D.new()
	camera.rotation_degrees = Vector3(-30.0, 90.0, 0.0)
	camera.position = Vector3(4.0, 3.0, 0.0)
	stage.add_child(camera)
	camera.make_current()
	var roller: Roller3D = stage.roller(door, Vector3(0.0, Stage3D.RADIUS, 0.0))
	assert_true(door.device.set_hand_target_3d(Vector3(0.0, 0.03, -0.05)))
	await _run_frames(60)
	assert_lt(roller.input_vector.x, -0.3, "forward is the camera's heading, the world's -x")
	assert_almost_eq(roller.input_vector.z, 0.0, 0.02, "nothing sideways")
	assert_gt(roller.input_vector.y, 0.1, "the stylus's height is the input's y")
	assert_lt(roller.position.x, -0.3, "rolled away from the camera")
	assert_almost_eq(roller.position.z, 0.0, 0.02)
	assert_almost_eq(roller.position.y, Stage3D.RADIUS, 0.02, "on the floor: the y left out")


func test_a_grid_map_cell_feels_like_its_items_material() -> void:
	var grid: GridMap = GridMap.new()
	var library: MeshLibrary = MeshLibrary.new()
	var names: PackedStringArray = ["stone", "moss"]
	for item: int in names.size():
		library.create_item(item)
		library.set_item_name(item, names[item])
		var shape: BoxShape3D = BoxShape3D.new()
		shape.size = Vector3.ONE
		library.set_item_shapes(item, [shape, Transform3D.IDENTITY])
	grid.mesh_library = library
	grid.cell_size = Vector3.ONE
	var moss: HapticMaterial = HapticMaterial.new()
	moss.stiffness = 0.7
	grid.set_meta(HapticMaterial.GRID_META, {"moss": moss})
	grid.set_cell_item(Vector3i(0, 0, -3), 0)
	grid.set_cell_item(Vector3i(2, 0, -3), 1)
	stage.add_child(grid)
	assert_null(HapticMaterial.of_grid_cell(grid, Vector3i(0, 0, -3)), "stone has none")
	assert_eq(HapticMaterial.of_grid_cell(grid, Vector3i(2, 0, -3)), moss)
	# Walk into the moss block: the frame's contact carries moss's stiffness.
	var walker: Explorer = stage.walker(door, Vector3(2.5, Stage3D.RADIUS, 0.0))
	assert_true(door.device.set_hand_target_3d(Vector3(0.0, 0.0, -0.05)))
	await _run_frames(90)
	var stiffness: Array[float] = []
	for contact: HapticContact3D in Stage3D.probe_of(walker).last_frame.contacts:
		if contact.normal.distance_to(Vector3.BACK) < 0.02 and contact.material != null:
			stiffness.append(contact.material.stiffness_n)
	assert_eq(stiffness, [0.7] as Array[float], "the moss cell's material")


func test_a_physics_material_stands_in_for_a_missing_haptic_one() -> void:
	var wall: StaticBody3D = stage.box(Vector3(6.0, 2.0, 0.5), Vector3(0.0, 1.0, -2.25))
	wall.physics_material_override = PhysicsMaterial.new()
	wall.physics_material_override.friction = 0.25
	var walker: Explorer = stage.walker(door, Vector3(0.0, Stage3D.RADIUS, 0.0))
	var probe: HapticProbe3D = Stage3D.probe_of(walker)
	probe.default_material = null
	assert_true(door.device.set_hand_target_3d(Vector3(0.0, 0.0, -0.05)))
	await _run_frames(90)
	var expected: float = (
		HapticMaterial.from_physics_material(wall.physics_material_override).friction
	)
	var found: Array[float] = []
	for contact: HapticContact3D in probe.last_frame.contacts:
		if contact.normal.distance_to(Vector3.BACK) < 0.02 and contact.material != null:
			found.append(contact.material.friction_n)
	assert_eq(found, [expected] as Array[float])


func test_a_shape_that_declares_its_own_material_wins_over_its_body() -> void:
	# One body of two shapes, as an imported level makes: the wall pressed, and a pillar far
	# off; the body, the wall and the pillar each declare a material.
	var wall: StaticBody3D = stage.box(Vector3(6.0, 2.0, 0.5), Vector3(0.0, 1.0, -2.25))
	wall.set_meta(&"haptic_material", _material(0.9))
	var pressed: CollisionShape3D = wall.find_children("*", "CollisionShape3D", false, false)[0]
	pressed.set_meta(&"haptic_material", _material(0.25))
	var pillar: CollisionShape3D = CollisionShape3D.new()
	pillar.shape = BoxShape3D.new()
	pillar.position = Vector3(20.0, 0.0, 0.0)
	pillar.set_meta(&"haptic_material", _material(0.5))
	wall.add_child(pillar)
	var walker: Explorer = stage.walker(door, Vector3(0.0, Stage3D.RADIUS, 0.0))
	var probe: HapticProbe3D = Stage3D.probe_of(walker)
	assert_true(door.device.set_hand_target_3d(Vector3(0.0, 0.0, -0.05)))
	await _run_frames(90)
	var found: Array[float] = []
	for contact: HapticContact3D in probe.last_frame.contacts:
		if contact.normal.distance_to(Vector3.BACK) < 0.02 and contact.material != null:
			found.append(contact.material.friction_n)
	assert_eq(found, [0.25] as Array[float], "the pressed shape's own")


func test_a_hit_from_game_code_rings_in_view_axes() -> void:
	var walker: Explorer = stage.walker(door, Vector3(0.0, Stage3D.RADIUS, 0.0))
	await _run_frames(5)
	var probe: HapticProbe3D = Stage3D.probe_of(walker)
	probe.hit(Vector3.BACK, 3.0)
	probe.hit(Vector3.ZERO, 3.0)  # No direction: nothing, and no error.
	HapticsTestKit.run(door, 3)
	var impact: Vector3 = door.get_forces_3d().impact
	assert_gt(impact.length(), 0.05, "the hit rings")
	assert_almost_eq(impact.normalized().abs(), Vector3.BACK, 0.01, "along depth")


func test_walking_across_grid_map_floor_cells_rings_only_the_landing() -> void:
	# The demos' GridMap floors (Jolt) gave a 0.2-0.45 m/s impact at every cell seam walked
	# over, their normals a few degrees apart there. Cells tilted 6° either way make the same
	# seams under any engine: one floor going on is no new touch.
	var grid: GridMap = GridMap.new()
	grid.mesh_library = MeshLibrary.new()
	for item: int in 2:
		grid.mesh_library.create_item(item)
		var shape: BoxShape3D = BoxShape3D.new()
		shape.size = Vector3.ONE
		var tilt: Basis = Basis(Vector3.BACK, deg_to_rad(6.0 if item == 0 else -6.0))
		grid.mesh_library.set_item_shapes(item, [shape, Transform3D(tilt, Vector3.ZERO)])
	grid.cell_size = Vector3.ONE
	for x: int in range(-1, 10):
		grid.set_cell_item(Vector3i(x, 0, 0), x % 2)
	grid.position = Vector3(0.0, 2.0, 0.0)
	stage.add_child(grid)
	var walker: Explorer = stage.walker(door, Vector3(0.5, 4.0, 0.5), true)
	var speeds: Array[float] = []
	Stage3D.probe_of(walker).impact.connect(
		func(_collider: Object, _normal: Vector3, speed: float) -> void: speeds.append(speed)
	)
	await _run_frames(40)
	assert_eq(speeds.size(), 1, "the landing: %s" % [speeds])
	assert_true(door.device.set_hand_target_3d(Vector3(0.08, 0.0, 0.0)))
	var start_x: float = walker.position.x
	await _run_frames(150)
	assert_gt(walker.position.x - start_x, 4.0, "walked over more than four cells")
	assert_eq(speeds.size(), 1, "no impact at the seams: %s" % [speeds])


static func _material(friction: float) -> HapticMaterial:
	var material: HapticMaterial = HapticMaterial.new()
	material.friction = friction
	return material
