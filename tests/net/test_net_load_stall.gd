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


func test_this_peers_own_stall_counts_against_no_one() -> void:
	var beat: PongNetHeartbeat = PongNetHeartbeat.new()
	var limit: Callable = func(_peer: int) -> float: return 1.0
	beat.watch(7, 0.0)
	beat.heard(7, 1.5)
	beat.frame(1.5)
	assert_eq(beat.overdue(1.5, limit), [] as Array[Array])
	beat.frame(6.6)  # The frame after the one that loaded the court: 5.1 s.
	assert_eq(beat.overdue(6.6, limit), [] as Array[Array], "5.1 s of our own stall")
	for frame: int in 50:
		beat.frame(6.6 + 0.02 * frame)  # Ordinary frames excuse nothing.
	assert_eq(beat.overdue(7.6, limit), [] as Array[Array], "1.0 s of silence since")
	beat.frame(7.7)
	assert_eq(beat.overdue(7.7, limit).size(), 1, "then its silence counts as ever: 1.1 s")
