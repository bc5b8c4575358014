extends TestSuite
## The constraint-based (finite proxy) renderer through [HapticsConstraint] over a door of
## the test's own, stepped manually: a maze 200 × 200 units with one thin vertical wall at
## x = 20, mapped onto the simulated device's 0.1 m workspace disc.

const K_C := 300.0
const RADIUS := 8.0
const MAZE_MIN := Vector2(-100.0, -100.0)
const MAZE_MAX := Vector2(100.0, 100.0)
const WALL := HapticConstraintFacts.ConstraintForce.WALL

var door: HapticsTestKit.Door = null
var constraint: HapticsConstraint = null


func before_each() -> void:
	door = autofree(HapticsTestKit.manual())
	constraint = HapticsConstraint.of(door)
	assert_true(HapticsTestKit.instant(door))
	var settings: HapticConstraintSettings = constraint.get_settings()
	settings.stiffness_n_per_m = K_C
	settings.proxy_radius = RADIUS
	settings.update = HapticConstraintFacts.ProxyUpdate.SERVO
	assert_true(constraint.apply_settings(settings))
	var wall: PackedVector2Array = [Vector2(20.0, -90.0), Vector2(20.0, 90.0)]
	assert_true(constraint.set_walls(wall, _mapping()))
	assert_true(constraint.activate())
	assert_true(constraint.is_active())
	assert_eq(door.get_render_mode(), HapticsConstraint.NAME)


func _mapping(maze_min: Vector2 = MAZE_MIN, maze_max: Vector2 = MAZE_MAX) -> HapticMazeMapping:
	var mapping: HapticMazeMapping = HapticMazeMapping.new()
	mapping.maze_min = maze_min
	mapping.maze_max = maze_max
	return mapping


# Ticks with an empty frame before each (the watchdog's heartbeat).
func _steps(count: int) -> void:
	assert_true(HapticsTestKit.run(door, count, HapticFrame.new()))


# Metres per maze unit for the DISC fit: the maze's diagonal spans the workspace diameter.
func _metres_per_unit() -> float:
	return 0.2 / (MAZE_MAX - MAZE_MIN).length()


func test_the_proxy_stops_at_the_wall_while_the_device_goes_past() -> void:
	assert_true(HapticsTestKit.set_hand_m(door, Vector2(-0.02, 0.0)))
	_steps(300)
	assert_true(constraint.get_proxy().placed, "placed in free space")
	assert_true(HapticsTestKit.set_hand_m(door, Vector2(0.06, 0.0)))
	_steps(400)
	var state: HapticProxyState = constraint.get_proxy()
	assert_gt(state.goal.x, 20.0 + RADIUS, "the device is past the wall")
	assert_almost_eq(state.proxy.x, 20.0 - RADIUS, 0.01, "the proxy rests against it")
	assert_eq(state.constraints, 1)
	assert_eq(state.geometry_segments, 1)


func test_the_force_is_k_c_times_proxy_minus_device() -> void:
	assert_true(HapticsTestKit.set_hand_m(door, Vector2(-0.02, 0.0)))
	_steps(300)
	assert_true(HapticsTestKit.set_hand_m(door, Vector2(0.05, 0.01)))
	_steps(400)
	var state: HapticProxyState = constraint.get_proxy()
	# Maze and game axes are both y-down, so the force reads the same in both.
	var expected: Vector2 = K_C * (state.proxy - state.goal) * _metres_per_unit()
	var forces: HapticForces = door.get_forces()
	var force: Vector2 = forces.parts[WALL]
	assert_lt(force.x, -0.5, "pulled back left, toward the proxy")
	assert_almost_eq(force, expected, 0.01)
	for part: int in range(WALL + 1, forces.parts.size()):
		assert_almost_eq(forces.parts[part], Vector2.ZERO, 1e-6, "the wall is its only force")


func test_the_papers_fifty_hertz_variant_moves_the_proxy_only_on_frames() -> void:
	var settings: HapticConstraintSettings = constraint.get_settings()
	settings.update = HapticConstraintFacts.ProxyUpdate.FRAME
	assert_true(constraint.apply_settings(settings))
	assert_true(HapticsTestKit.set_hand_m(door, Vector2(-0.03, 0.0)))
	var before: int = constraint.get_proxy().updates
	for frame: int in 10:
		assert_true(door.submit_frame(HapticFrame.new()))
		assert_true(HapticsTestKit.run(door, 20))
	var updates: int = constraint.get_proxy().updates
	assert_eq(updates - before, 10, "one proxy update per 50 Hz frame")


func test_bad_walls_are_refused_and_the_old_walls_stay() -> void:
	_steps(2)
	var generation: int = constraint.get_proxy().geometry_generation
	expect_error("HapticMazeWalls.points: 1 points; walls are point pairs, so it must be even")
	assert_false(constraint.set_walls(PackedVector2Array([Vector2.ZERO]), _mapping()))
	expect_error("HapticMazeWalls.points[0]: not finite (nan, 0")
	assert_false(
		constraint.set_walls(PackedVector2Array([Vector2(NAN, 0.0), Vector2(1.0, 1.0)]), _mapping())
	)
	expect_error("mapping.maze_max.x must be > mapping.maze_min.x")
	assert_false(constraint.set_walls(PackedVector2Array(), _mapping(MAZE_MIN, MAZE_MIN)))
	_steps(2)
	var state: HapticProxyState = constraint.get_proxy()
	assert_eq(state.geometry_segments, 1, "the wall is still there")
	assert_eq(state.geometry_generation, generation, "no new geometry was taken")


func test_unknown_modes_and_settings_are_refused() -> void:
	expect_error("unknown renderer 'joystick'")
	assert_false(door.set_render_mode(&"joystick"))
	assert_true(constraint.is_active())
	var settings: HapticConstraintSettings = constraint.get_settings()
	settings.proxy_radius = -1.0
	expect_error("HapticConstraintSettings.proxy_radius")
	assert_false(constraint.apply_settings(settings))
	assert_eq(constraint.get_settings().proxy_radius, RADIUS, "unchanged")
	assert_eq(constraint.get_settings().update, HapticConstraintFacts.ProxyUpdate.SERVO)


func test_back_to_movement_mode() -> void:
	assert_true(door.set_render_mode(&"movement"))
	assert_false(constraint.is_active())
	assert_true(HapticsTestKit.set_hand_m(door, Vector2(0.05, 0.0)))
	_steps(100)
	assert_almost_eq(door.get_forces().total, Vector2.ZERO, 1e-4, "no contacts, no force")
