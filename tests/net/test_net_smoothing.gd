extends TestSuite
## How a follower orders, dates and carries on the master's states, without sockets: the
## jitter buffer (PongNetBallBuffer) on scripted streams, the extrapolation, the clock.

const PongTestCourt := preload("res://tests/pong/pong_test_court.gd")
const ScriptedBallPath := preload("res://tests/net/scripted_ball_path.gd")

## The master's stream period at MAX_STREAM_HZ, and the follower's frame period.
const SEND_PERIOD_S: float = 1.0 / PongNetPlay.MAX_STREAM_HZ
const FRAME_S: float = 1.0 / 60.0


func test_in_order_states_play_at_once_and_a_reordered_one_fills_its_gap() -> void:
	var buffer: PongNetBallBuffer = PongNetBallBuffer.new()
	assert_eq(buffer.push(_state(1, 0.0, 0.1)), PongNetBallBuffer.Taken.NEWEST)
	assert_true(buffer.advance(0.1))
	assert_eq(buffer.played.seq, 1)
	# 3 overtakes 2: it waits for the gap, and 2, arriving in time, is played before it.
	assert_eq(buffer.push(_state(3, 0.016, 0.111)), PongNetBallBuffer.Taken.NEWEST)
	buffer.delay_s = 0.05  # As if measured: the test is about the order, not the size.
	assert_false(buffer.advance(0.112), "3 waits for 2")
	assert_eq(buffer.push(_state(2, 0.008, 0.113)), PongNetBallBuffer.Taken.FILLS_GAP)
	assert_true(buffer.advance(0.114))
	assert_eq(buffer.played.seq, 3, "2 then 3, in one frame")
	assert_eq(buffer.used, 3)
	# A copy is a duplicate; a state behind the play is late; both are dropped.
	assert_eq(buffer.push(_state(3, 0.016, 0.12)), PongNetBallBuffer.Taken.DUPLICATE)
	assert_eq(buffer.push(_state(5, 0.032, 0.13)), PongNetBallBuffer.Taken.NEWEST)
	assert_false(buffer.advance(0.131), "5 waits for 4")
	assert_true(buffer.advance(0.032 + 0.1 + 0.05 + 0.001), "then gives 4 up")
	assert_eq(buffer.played.seq, 5)
	assert_eq(buffer.push(_state(4, 0.024, 0.2)), PongNetBallBuffer.Taken.LATE)
	assert_eq([buffer.received, buffer.used, buffer.late, buffer.duplicates], [4, 4, 1, 1])
	assert_eq(buffer.late_after_news, 0, "4 was given up when the wait ran out")
	assert_eq(buffer.news, 0)
	# A new stream (a transfer) starts afresh: its first state plays whatever its number.
	buffer.restart()
	assert_eq(buffer.push(_state(2, 1.0, 1.1)), PongNetBallBuffer.Taken.NEWEST)
	assert_true(buffer.advance(1.1))
	assert_eq(buffer.played.seq, 2)


func test_a_gap_is_not_waited_for_past_a_strike() -> void:
	var buffer: PongNetBallBuffer = PongNetBallBuffer.new()
	buffer.push(_state(1, 0.0, 0.1))
	buffer.advance(0.1)
	var calm: Callable = func(_a: PongNetBallBuffer.State, _b: PongNetBallBuffer.State) -> bool:
		return true
	var struck: Callable = func(_a: PongNetBallBuffer.State, _b: PongNetBallBuffer.State) -> bool:
		return false
	buffer.push(_state(3, 0.016, 0.12))
	buffer.delay_s = 0.1  # As if measured.
	assert_false(buffer.advance(0.121, calm), "where the flight leads: 3 waits for 2")
	assert_true(buffer.advance(0.121, struck), "news: 3 is played at once")
	assert_eq(buffer.played.seq, 3)
	assert_eq(buffer.skipped, 1, "the gap given up")
	assert_eq(buffer.push(_state(2, 0.008, 0.13)), PongNetBallBuffer.Taken.LATE)
	assert_eq(buffer.late_after_news, 1, "2 was given up for the news")
	assert_eq(buffer.news, 1, "one play gave a gap up for news")


func test_the_wait_is_sized_from_the_measured_jitter() -> void:
	var rng: RandomNumberGenerator = RandomNumberGenerator.new()
	rng.seed = 7
	var steady: PongNetBallBuffer = PongNetBallBuffer.new()
	var jittery: PongNetBallBuffer = PongNetBallBuffer.new()
	var awful: PongNetBallBuffer = PongNetBallBuffer.new()
	for seq: int in 200:
		var sent: float = seq * SEND_PERIOD_S
		steady.push(_state(seq, sent, sent + 0.05))
		jittery.push(_state(seq, sent, sent + 0.05 + rng.randf_range(0.0, 0.12)))
		awful.push(_state(seq, sent, sent + 0.05 + rng.randf_range(0.0, 2.0)))
	assert_almost_eq(steady.delay_s, 0.0, 1e-6, "no jitter, no wait")
	# The 95th percentile of U(0, 120 ms) is 114 ms; 64 samples scatter it by a few ms.
	assert_almost_eq(jittery.delay_s, 0.114, 0.012, "sized to the jitter")
	assert_almost_eq(awful.delay_s, PongNetBallBuffer.MAX_DELAY_S, 1e-6, "capped")


func test_the_issue_path_keeps_nine_states_in_ten_that_arrive() -> void:
	# Issue 24's path: 200 +- 60 ms per datagram, 10 % loss in bursts of 3-10, 1 % copies;
	# the master streams at 125 Hz for 30 s, the follower plays at 60 Hz.
	var path: ScriptedBallPath = ScriptedBallPath.new()
	var deliveries: Array[Array] = []  # [arrival, seq, sent]
	var seconds: float = 30.0
	var sends: int = roundi(seconds / SEND_PERIOD_S)
	for seq: int in sends:
		var sent: float = seq * SEND_PERIOD_S
		for arrival: float in path.arrivals(sent):
			deliveries.append([arrival, seq, sent])
	deliveries.sort_custom(func(a: Array, b: Array) -> bool: return a[0] < b[0])
	# What an unreliable_ordered channel kept: only states newer than all before them.
	var newest_seq: int = -1
	var ordered_kept: int = 0
	var reached: Dictionary[int, bool] = {}
	for d: Array in deliveries:
		var seq: int = d[1]
		reached[seq] = true
		if seq > newest_seq:
			newest_seq = seq
			ordered_kept += 1
	var buffer: PongNetBallBuffer = PongNetBallBuffer.new()
	var next: int = 0
	var last_played: int = -1
	var out_of_order: int = 0
	var frame_time: float = 0.0
	while frame_time < seconds + 1.0:
		while next < deliveries.size() and deliveries[next][0] <= frame_time:
			var d: Array = deliveries[next]
			var seq: int = d[1]
			var sent: float = d[2]
			var arrival: float = d[0]
			buffer.push(_state(seq, sent, arrival))
			next += 1
		if buffer.advance(frame_time):
			out_of_order += 1 if buffer.played.seq <= last_played else 0
			last_played = buffer.played.seq
		frame_time += FRAME_S
	var used_share: float = float(buffer.used) / reached.size()
	var ordered_share: float = float(ordered_kept) / reached.size()
	print(
		(
			(
				"issue path: %d sent, %.1f %% lost, %d copies; of %d that reached the follower the "
				+ "buffer used %.1f %% (wait %.0f ms), an ordered channel would keep %.1f %%"
			)
			% [
				path.sent,
				100.0 * path.lost / path.sent,
				path.copies,
				reached.size(),
				100.0 * used_share,
				buffer.delay_s * 1000.0,
				100.0 * ordered_share,
			]
		)
	)
	assert_almost_eq(float(path.lost) / path.sent, 0.1, 0.03, "the path loses about 10 %")
	assert_gt(path.copies, 0, "and copies some")
	assert_lt(ordered_share, 0.5, "the path reorders: an ordered channel loses most states")
	assert_gt(used_share, 0.9, "the buffer uses nine in ten of those that arrive")
	assert_eq(out_of_order, 0, "played in sequence order")
	assert_eq(buffer.duplicates, path.copies, "every copy recognised")
	assert_eq(buffer.received + buffer.late, reached.size(), "each state counted once")


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


func test_quantiles_and_correction_sizes() -> void:
	var values: PackedFloat32Array = PackedFloat32Array([5, 1, 4, 2, 3])
	assert_eq(PongNetSmoother.quantile(values, 0.5), 3.0)
	assert_eq(PongNetSmoother.quantile(values, 1.0), 5.0)
	assert_eq(PongNetSmoother.quantile(PackedFloat32Array(), 0.99), 0.0)
	var smoother: PongNetSmoother = PongNetSmoother.new()
	smoother.record(Vector3.ZERO, Vector3(0.3, 0.4, 0.0))
	assert_almost_eq(smoother.sizes[0], 0.5, 1e-6, "the correction's size is recorded")


## State [param seq] sent at [param sent] (sender's clock) arrived at [param arrival] (ours:
## the same clock here, so its age is the difference).
func _state(seq: int, sent: float, arrival: float) -> PongNetBallBuffer.State:
	var ball: Array[Vector3] = [Vector3(0, 1, 0), Vector3.ZERO, Vector3.ZERO]
	return PongNetBallBuffer.State.new(seq, sent, ball, arrival, arrival - sent)


func test_a_forged_stamp_never_becomes_the_clock_every_later_state_is_aged_from() -> void:
	var clock: PongNetClock = PongNetClock.new()
	clock.base_latency_s = 0.05
	for i: int in 10:
		assert_almost_eq(clock.observe(10.0 + i * 0.016, 110.0 + i * 0.016 - 0.05), 0.05, 1e-6)
	# The issue's attack: a well-formed state stamped 9.9e6 s.
	assert_eq(clock.observe(10.2, 9.9e6), PongNetClock.REFUSED, "it would arrive before it left")
	assert_eq(clock.observe(10.2, INF), PongNetClock.REFUSED, "not a time")
	assert_almost_eq(clock.observe(10.3, 110.25), 0.05, 1e-6, "the honest ones keep their ages")
	assert_almost_eq(clock.observe(10.4, 110.3), 0.1, 1e-3, "a late one is older by its delay")
	# A sender whose first stamp was the forgery: the honest run that follows takes over.
	clock.reset()
	assert_almost_eq(clock.observe(20.0, 9.9e6), 0.05, 1e-9, "nothing to judge it by yet")
	var ages: Array[float] = []
	for i: int in PongNetClock.RUN + 3:
		ages.append(clock.observe(20.1 + i * 0.016, 120.05 + i * 0.016))
	assert_almost_eq(ages[-1], 0.05, 1e-6, "aged rightly again after %d states" % PongNetClock.RUN)
	assert_almost_eq(ages[PongNetClock.RUN - 1], 0.05, 1e-6)
