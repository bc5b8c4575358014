extends TestSuite
## The addon's 3D water: rigid bodies float or sink by their density against the water's, and
## the 3D probe feels it as water, in and out.

## Runs scenes for seconds: make check (--quick) leaves it out.
const SLOW := true

const SURFACE_Y := 2.0

var stage: Stage3D = null
var water: HapticWater3D = null


func before_each() -> void:
	stage = Stage3D.new()
	add_child_autofree(stage)
	water = stage.water(Vector3(8.0, SURFACE_Y, 8.0), Vector3(0.0, SURFACE_Y / 2.0, 0.0))
	water.drag_coefficient = 0.7
	water.inertia_force = 0.3


func test_the_surface_is_the_boxs_top() -> void:
	assert_almost_eq(water.get_surface_y(), SURFACE_Y, 1e-5)


func test_a_light_crate_floats_at_the_surface_and_a_dense_one_sinks() -> void:
	var light: RigidBody3D = stage.crate(1.0, 0.4, Vector3(-2.0, SURFACE_Y + 0.6, 0.0))
	light.set_meta(&"density", 0.5)
	var dense: RigidBody3D = stage.crate(1.0, 0.4, Vector3(2.0, SURFACE_Y + 0.6, 0.0))
	dense.set_meta(&"density", 2.0)
	for frame: int in 300:
		await get_tree().physics_frame
	assert_almost_eq(light.position.y, SURFACE_Y, 0.15, "half submerged at the surface")
	assert_almost_eq(dense.position.y, 0.2, 0.02, "resting on the bottom")
	assert_almost_eq(water.buoyancy_of(light), 1.0, 0.2, "lift about its weight")


func test_the_3d_probe_feels_it_as_water_inside_and_not_above() -> void:
	var door: HapticsTestKit.Door = autofree(HapticsTestKit.manual())
	var walker: Explorer = stage.walker(door, Vector3(0.0, Stage3D.RADIUS, 0.0))
	for frame: int in 3:
		await get_tree().physics_frame
	var felt: HapticFrame3D = Stage3D.probe_of(walker).last_frame
	assert_true(felt.in_water, "inside")
	assert_almost_eq(felt.water_drag_n_s_per_m, 0.7, 1e-6)
	assert_almost_eq(felt.water_inertia_n, 0.3, 1e-6)
	walker.position = Vector3(6.0, Stage3D.RADIUS, 6.0)  # Outside, on the dry floor.
	for frame: int in 2:
		await get_tree().physics_frame
	assert_false(Stage3D.probe_of(walker).last_frame.in_water, "out of it")
