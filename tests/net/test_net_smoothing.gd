extends TestSuite
## How a follower corrects its ball and dates the master's states, without sockets.

const PongTestCourt := preload("res://tests/pong/pong_test_court.gd")


func test_a_small_error_is_blended_out_over_about_three_time_constants() -> void:
	var smoother: PongNetSmoother = PongNetSmoother.new()
	assert_false(smoother.on_target(Vector3.ZERO, Vector3(0.2, 0, 0)))
	var applied: Vector3 = Vector3.ZERO
	var steps: int = 0
	while smoother.pending.length() > 0.01:
		var part: Vector3 = smoother.take(1.0 / 60.0)
		assert_lt(part.length(), 0.2 * 0.5, "never more than half in one frame")
		applied += part
		steps += 1
	assert_almost_eq(applied.x + smoother.pending.x, 0.2, 1e-5, "nothing lost")
	var seconds: float = steps / 60.0
	assert_gt(seconds, 0.08)
	assert_lt(seconds, 0.2, "95 %% gone in about 120 ms (took %.3f s)" % seconds)
	assert_almost_eq(smoother.sizes[0], 0.2, 1e-6, "the correction's size is recorded")


func test_a_huge_error_snaps_and_is_counted() -> void:
	var smoother: PongNetSmoother = PongNetSmoother.new()
	smoother.pending = Vector3(0.1, 0, 0)
	assert_true(smoother.on_target(Vector3.ZERO, Vector3(0, 0, smoother.snap_distance_m + 0.1)))
	assert_eq(smoother.snaps, 1)
	assert_eq(smoother.pending, Vector3.ZERO)


func test_extrapolation_follows_the_ballistic_flight_and_bounces() -> void:
	var court: PongCourt = PongTestCourt.make()
	var predictor: PongPredictor = PongPredictor.new(court)
	var moved: Array[Vector3] = PongNetSmoother.extrapolate(
		predictor, Vector3(0, 1.5, 0), Vector3(0, 0, 2), court.gravity, 0.2
	)
	assert_almost_eq(moved[0].z, 0.4, 1e-4)
	assert_almost_eq(moved[0].y, 1.5 - 0.5 * court.gravity * 0.04, 1e-4)
	assert_almost_eq(moved[1].y, -court.gravity * 0.2, 1e-4)
	var bounced: Array[Vector3] = PongNetSmoother.extrapolate(
		predictor, Vector3(0, court.ball_radius + 0.01, 0), Vector3(0, -3, 0), court.gravity, 0.05
	)
	assert_gt(bounced[1].y, 0.0, "the floor bounce is carried along")
	var unchanged: Array[Vector3] = PongNetSmoother.extrapolate(
		predictor, Vector3.ONE, Vector3.ONE, court.gravity, 0.0
	)
	assert_eq(unchanged, [Vector3.ONE, Vector3.ONE] as Array[Vector3])


func test_a_late_state_is_older_by_its_extra_delay() -> void:
	var clock: PongNetClock = PongNetClock.new()
	clock.base_latency_s = 0.05
	# The sender's clock is 100 s ahead of ours; the path takes 50 ms at best.
	assert_almost_eq(clock.observe(10.05, 110.0), 0.05, 1e-9)
	assert_almost_eq(clock.observe(10.07, 110.01), 0.06, 1e-4, "10 ms of jitter")
	assert_almost_eq(clock.observe(10.10, 110.05), 0.05, 1e-3, "fast again")
	clock.reset()
	assert_almost_eq(clock.observe(20.0, 5.0), 0.05, 1e-9, "a new sender starts over")


func test_quantiles() -> void:
	var values: PackedFloat32Array = PackedFloat32Array([5, 1, 4, 2, 3])
	assert_eq(PongNetSmoother.quantile(values, 0.5), 3.0)
	assert_eq(PongNetSmoother.quantile(values, 1.0), 5.0)
	assert_eq(PongNetSmoother.quantile(PackedFloat32Array(), 0.99), 0.0)
