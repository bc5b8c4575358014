extends TestSuite
## The addon's self-contained water: the probe feels it as water, and rigid bodies float or
## sink by their density against the water's, with nothing from this game around it.

## Runs scenes or processes for seconds: make check (--quick) leaves it out.
const SLOW := true

const SURFACE_Y := 300.0
const BOTTOM_Y := 600.0

var world: Node2D = null
var water: HapticWater = null


func before_each() -> void:
	world = Node2D.new()
	water = _make_water()
	water.drag_coefficient = 0.7
	water.inertia_force = 0.3
	water.add_child(_box(Vector2(800.0, BOTTOM_Y - SURFACE_Y)))
	water.position = Vector2(400.0, (SURFACE_Y + BOTTOM_Y) * 0.5)
	world.add_child(water)
	var bottom: StaticBody2D = StaticBody2D.new()
	bottom.add_child(_box(Vector2(800.0, 40.0)))
	bottom.position = Vector2(400.0, BOTTOM_Y + 20.0)
	world.add_child(bottom)
	add_child_autofree(world)


## The water under test (a suite that extends this one tests its own kind of water).
func _make_water() -> HapticWater:
	return HapticWater.new()


func _box(size: Vector2) -> CollisionShape2D:
	var shape: CollisionShape2D = CollisionShape2D.new()
	var rect: RectangleShape2D = RectangleShape2D.new()
	rect.size = size
	shape.shape = rect
	return shape


func _crate(density: float, x: float) -> RigidBody2D:
	var crate: RigidBody2D = RigidBody2D.new()
	crate.set_meta(&"density", density)
	crate.add_child(_box(Vector2(40.0, 40.0)))
	crate.position = Vector2(x, SURFACE_Y - 60.0)
	world.add_child(crate)
	return crate


func test_a_light_body_floats_at_the_surface_and_a_dense_one_sinks() -> void:
	var light: RigidBody2D = _crate(0.5, 200.0)
	var dense: RigidBody2D = _crate(2.0, 600.0)
	for frame: int in 250:
		await get_tree().physics_frame
	assert_almost_eq(light.position.y, SURFACE_Y, 20.0, "half submerged at the surface")
	assert_almost_eq(dense.position.y, BOTTOM_Y - 20.0, 2.0, "resting on the bottom")


func test_the_probe_feels_it_as_water() -> void:
	var body: CharacterBody2D = CharacterBody2D.new()
	body.add_child(_box(Vector2(20.0, 36.0)))
	body.position = Vector2(400.0, 450.0)
	var probe: HapticProbe = HapticProbe.new()
	probe.haptics = autofree(HapticsTestKit.manual())
	body.add_child(probe)
	world.add_child(body)
	for frame: int in 3:
		await get_tree().physics_frame
	var felt: HapticFrame = probe.last_frame
	assert_true(felt.in_water, "inside")
	assert_almost_eq(felt.water_drag_n_s_per_m, 0.7, 1e-6)
	assert_almost_eq(felt.water_inertia_n, 0.3, 1e-6)
	body.position.y = 100.0
	for frame: int in 2:
		await get_tree().physics_frame
	assert_false(probe.last_frame.in_water, "out of it above the surface")
