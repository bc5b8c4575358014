extends TestSuite
## The heartbeat, without sockets: its timeout follows the path within 1 to 3 s, it beats at
## 5 Hz without catching up after a stall, a silent peer is overdue once and a heard one
## never, a new peer has the handshake's bound for its first beat, and a peer that says it
## stalls may be silent until its next beat.


func test_the_heartbeat_timeout_follows_the_path_within_one_to_three_seconds() -> void:
	var timeout: Callable = PongNetProtocol.heartbeat_timeout_s
	var misses: float = PongNetProtocol.HEARTBEAT_MISSES / PongNetProtocol.HEARTBEAT_HZ
	assert_almost_eq(misses, 0.8, 1e-9, "four beats at 5 Hz")
	assert_almost_eq(timeout.call(0.0, 0.0), 1.0, 1e-9, "a LAN: the floor")
	assert_almost_eq(timeout.call(0.12, 0.01), 1.0, 1e-9, "50 ms each way: still the floor")
	assert_almost_eq(timeout.call(0.34, 0.02), 0.8 + 0.34 + 0.08, 1e-9, "150 ms: misses + rtt")
	assert_almost_eq(timeout.call(2.0, 0.5), 3.0, 1e-9, "a terrible path: the ceiling")
	assert_almost_eq(timeout.call(-5.0, -1.0), 1.0, 1e-9, "nonsense measures: the floor")
	var last: float = 0.0
	for rtt_ms: int in range(0, 3000, 50):
		var t: float = timeout.call(rtt_ms / 1000.0, rtt_ms / 8000.0)
		assert_true(t >= last and t >= 1.0 and t <= 3.0, "monotonic and bounded at %d ms" % rtt_ms)
		last = t


func test_the_heartbeat_beats_at_five_hertz_without_catching_up_after_a_stall() -> void:
	var beat: PongNetHeartbeat = PongNetHeartbeat.new()
	var sent: int = 0
	for frame: int in 1000:  # 1 s of 1 ms frames
		sent += 1 if beat.due(10.0 + frame * 0.001) else 0
	assert_eq(sent, 5, "five beats in a second")
	assert_true(beat.due(14.0), "after a 3 s stall: a beat at once")
	assert_false(beat.due(14.001), "but one, not the fifteen missed")


func test_a_silent_peer_is_overdue_once_and_a_heard_one_never() -> void:
	var beat: PongNetHeartbeat = PongNetHeartbeat.new()
	beat.watch(7, 99.0)
	beat.watch(8, 99.0)
	beat.heard(7, 100.0)
	var limit: Callable = func(_peer: int) -> float: return 1.0
	for step: int in 5:
		beat.heard(8, 100.0 + step * 0.2)
		assert_eq(beat.overdue(100.0 + step * 0.2, limit), [], "nobody silent for 1 s yet")
	beat.heard(8, 101.8)
	var dead: Array[Array] = beat.overdue(101.8, limit)
	assert_eq(dead.size(), 1, "peer 7 has been silent 1.8 s")
	assert_eq(dead[0][0], 7)
	assert_almost_eq(dead[0][1], 1.8, 1e-6)
	assert_eq(beat.overdue(105.0, limit).size(), 1, "peer 8 now, peer 7 not again")
	beat.heard(7, 106.0)
	assert_eq(beat.peers(), [], "a beat from a peer not watched is ignored")


func test_a_peer_has_the_handshakes_bound_for_its_first_beat_then_its_paths() -> void:
	var beat: PongNetHeartbeat = PongNetHeartbeat.new()
	var limit: Callable = func(_peer: int) -> float: return 1.0
	var first: float = PongNetProtocol.FIRST_BEAT_TIMEOUT_S
	assert_gt(first, PongNetProtocol.HEARTBEAT_TIMEOUT_MAX_S, "longer than any path's limit")
	beat.watch(7, 0.0)
	beat.watch(8, 0.0)
	assert_eq(beat.overdue(first - 0.01, limit), [], "still in its side of the handshake")
	beat.heard(8, first - 0.01)
	var dead: Array[Array] = beat.overdue(first + 0.01, limit)
	assert_eq(dead.size(), 1, "the one never heard, once its bound is over")
	assert_eq(dead[0][0], 7)
	assert_almost_eq(dead[0][2], first, 1e-9, "reported with that bound")
	assert_eq(beat.overdue(first + 0.98, limit), [], "peer 8, heard, has its path's 1 s")
	assert_eq(beat.overdue(first + 1.0, limit).size(), 1, "then is overdue")


func test_a_peer_that_says_it_stalls_may_be_silent_until_its_next_beat() -> void:
	var beat: PongNetHeartbeat = PongNetHeartbeat.new()
	beat.watch(7, 0.0)
	beat.heard(7, 1.0)
	beat.stalls(7, 1.1)
	assert_true(beat.is_stalling(7))
	assert_almost_eq(beat.silence_s(7, 2.6), 1.5, 1e-9, "silent since its notice")
	beat.heard(7, 2.6)
	assert_false(beat.is_stalling(7), "its next beat ends the stall")
	beat.stalls(9, 3.0)
	assert_false(beat.is_stalling(9), "a peer not watched cannot stall")
