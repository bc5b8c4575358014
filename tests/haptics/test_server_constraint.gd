extends TestSuite
## The constraint-based (finite proxy) renderer through the binding, stepped manually: a
## maze 200 × 200 units with one thin vertical wall at x = 20, mapped onto the simulated
## device's 0.1 m workspace disc.

const K_C := 300.0
const RADIUS := 8.0
const MAZE_MIN := Vector2(-100.0, -100.0)
const MAZE_MAX := Vector2(100.0, 100.0)

var server: HapticsServer = null


func before_each() -> void:
	server = HapticsServer.new()
	assert_true(server.open_device("simulated"))
	assert_true(server.set_config("safety", {"startup_ramp_s": 0.0, "slew_rate_n_per_s": 0.0}))
	assert_true(
		(
			server
			. set_config(
				"constraint",
				{
					"stiffness_n_per_m": K_C,
					"proxy_radius": RADIUS,
					"update": HapticsServer.PROXY_UPDATE_SERVO_RATE,
				}
			)
		)
	)
	var wall: PackedVector2Array = [Vector2(20.0, -90.0), Vector2(20.0, 90.0)]
	assert_true(server.set_constraint_geometry(wall, {"maze_min": MAZE_MIN, "maze_max": MAZE_MAX}))
	assert_true(server.set_render_mode(HapticsServer.RENDER_MODE_CONSTRAINT))
	assert_eq(server.get_render_mode(), HapticsServer.RENDER_MODE_CONSTRAINT)


func after_each() -> void:
	server.close_device()


func _steps(count: int) -> void:
	for i: int in count:
		server.submit_frame({})
		server.step(0.001)


# Metres per maze unit for the DISC fit: the maze's diagonal spans the workspace diameter.
func _metres_per_unit() -> float:
	return 0.2 / (MAZE_MAX - MAZE_MIN).length()


func test_the_proxy_stops_at_the_wall_while_the_device_goes_past() -> void:
	assert_true(server.set_hand_target(Vector2(-0.02, 0.0)))
	_steps(300)
	assert_true(server.get_proxy_state()["placed"], "placed in free space")
	assert_true(server.set_hand_target(Vector2(0.06, 0.0)))
	_steps(400)
	var state: Dictionary = server.get_proxy_state()
	var proxy: Vector2 = state["position"]
	var goal: Vector2 = state["goal"]
	assert_gt(goal.x, 20.0 + RADIUS, "the device is past the wall")
	assert_almost_eq(proxy.x, 20.0 - RADIUS, 0.01, "the proxy rests against it")
	assert_eq(state["constraints"], 1)
	assert_eq(state["geometry_segments"], 1)


func test_the_force_is_k_c_times_proxy_minus_device() -> void:
	assert_true(server.set_hand_target(Vector2(-0.02, 0.0)))
	_steps(300)
	assert_true(server.set_hand_target(Vector2(0.05, 0.01)))
	_steps(400)
	var state: Dictionary = server.get_proxy_state()
	var proxy: Vector2 = state["position"]
	var goal: Vector2 = state["goal"]
	# Maze and game axes are both y-down, so the force reads the same in both.
	var expected: Vector2 = K_C * (proxy - goal) * _metres_per_unit()
	var force: Vector2 = server.get_forces()["normal"]
	assert_lt(force.x, -0.5, "pulled back left, toward the proxy")
	assert_almost_eq(force, expected, 0.01)
	assert_almost_eq(server.get_forces()["friction"], Vector2.ZERO, 1e-6)


func test_the_papers_fifty_hertz_variant_moves_the_proxy_only_on_frames() -> void:
	assert_true(server.set_config("constraint", {"update": "frame"}))
	assert_true(server.set_hand_target(Vector2(-0.03, 0.0)))
	var before: int = server.get_proxy_state()["updates"]
	for frame: int in 10:
		server.submit_frame({})
		for tick: int in 20:
			server.step(0.001)
	var updates: int = server.get_proxy_state()["updates"]
	assert_eq(updates - before, 10, "one proxy update per 50 Hz frame")


func test_bad_geometry_is_refused_and_the_old_walls_stay() -> void:
	expect_error("walls are point pairs")
	assert_false(
		server.set_constraint_geometry(
			PackedVector2Array([Vector2.ZERO]), {"maze_min": MAZE_MIN, "maze_max": MAZE_MAX}
		)
	)
	expect_error("segments[0]")
	assert_false(
		server.set_constraint_geometry(
			PackedVector2Array([Vector2(NAN, 0.0), Vector2(1.0, 1.0)]),
			{"maze_min": MAZE_MIN, "maze_max": MAZE_MAX}
		)
	)
	expect_error("mapping.maze_max: missing")
	assert_false(server.set_constraint_geometry(PackedVector2Array(), {"maze_min": MAZE_MIN}))
	_steps(2)
	assert_eq(server.get_proxy_state()["geometry_segments"], 1, "the wall is still there")


func test_unknown_modes_and_settings_are_refused() -> void:
	expect_error("unknown mode 9")
	assert_false(server.set_render_mode(9))
	assert_eq(server.get_render_mode(), HapticsServer.RENDER_MODE_CONSTRAINT)
	expect_error("constraint.update must be")
	assert_false(server.set_config("constraint", {"update": "sometimes"}))
	assert_eq(server.get_config()["constraint"]["update"], HapticsServer.PROXY_UPDATE_SERVO_RATE)


func test_back_to_movement_mode() -> void:
	assert_true(server.set_render_mode(HapticsServer.RENDER_MODE_MOVEMENT))
	assert_true(server.set_hand_target(Vector2(0.05, 0.0)))
	_steps(100)
	assert_almost_eq(server.get_forces()["total"], Vector2.ZERO, 1e-4, "no contacts, no force")
