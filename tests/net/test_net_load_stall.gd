extends TestSuite
## A peer loading a match's court (its first frames compile shaders, seconds on a slow
## machine): what it tells its partners, and how long each end of the connection waits.


func test_a_peer_loading_a_court_sends_stall_notices_for_its_first_frames_not_beats() -> void:
	var beat: PongNetHeartbeat = PongNetHeartbeat.new()
	assert_false(beat.settling(), "nothing announced: beats as usual")
	beat.settle()
	var notices: int = 0
	for _frame: int in PongNetHeartbeat.SETTLE_FRAMES + 5:
		notices += 1 if beat.settling() else 0
	assert_eq(notices, PongNetHeartbeat.SETTLE_FRAMES, "one notice a frame while it settles")
	beat.settle()
	beat.clear()
	assert_false(beat.settling(), "a closed session settles nothing")


func test_a_peer_loading_a_court_is_waited_for_by_the_heartbeat_and_by_enet() -> void:
	var beat: PongNetHeartbeat = PongNetHeartbeat.new()
	beat.watch(7, 0.0)
	assert_false(beat.is_stalling(7), "nobody loads: the path's own limit")
	beat.stalls(7, 1.0)
	assert_true(beat.is_stalling(7), "the peer said it loads a court")
	beat.heard(7, 2.0)
	assert_false(beat.is_stalling(7), "it beat again: loaded")
	var patience_s: float = PongNetProtocol.ENET_PATIENCE_MS / 1000.0
	assert_gt(patience_s, PongNetProtocol.LOAD_STALL_TIMEOUT_S, "ENet outwaits a court's load")
	assert_gt(patience_s, PongNetProtocol.SEAT_GRACE_S, "and a kept seat's grace")


func test_this_peers_own_stall_is_told_and_slow_frames_hide_no_silence() -> void:
	var beat: PongNetHeartbeat = PongNetHeartbeat.new()
	var limit: Callable = func(_peer: int) -> float: return 1.0
	beat.watch(7, 0.0)
	beat.heard(7, 1.5)
	assert_false(beat.frame(1.5), "the first frame: no gap to judge")
	assert_true(beat.frame(6.6), "the frame after the one that loaded a court: 5.1 s")
	# The pulse then reads what came meanwhile (PongNetPulse.frame): a beat of the peer's.
	beat.heard(7, 6.6)
	assert_eq(beat.overdue(6.6, limit), [] as Array[Array], "heard after the stall")
	for frame: int in 50:
		assert_false(beat.frame(6.62 + 0.02 * frame), "ordinary frames are no stall")
	# A game that draws three frames a second: every frame is a "stall", and the silence of a
	# peer that is gone still counts (excusing each gap once hid a dead server for 9 s).
	var now: float = 7.6
	var found: float = -1.0
	while now < 12.0 and found < 0.0:
		now += 0.34
		beat.frame(now)
		if not beat.overdue(now, limit).is_empty():
			found = now - 6.6
	assert_true(found > 1.0 and found < 1.4, "overdue %.2f s after the last beat" % found)
