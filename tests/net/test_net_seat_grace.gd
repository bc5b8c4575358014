extends "res://tests/net/net_play_suite.gd"
## A player whose packets stop for a while (a Wi-Fi hiccup) keeps the seat: the heartbeat
## counts it absent instead of gone, the server's computer stands in for it, and the seat,
## with the ball when it is there, is the player's again as soon as it is heard; only a
## silence past the grace gives the seat up. Without sockets: the heartbeat's times are
## passed in, and the server is the host of a real stepped match.

const FRAME_S: float = 1.0 / 60.0


func test_a_silent_player_is_absent_once_back_when_heard_and_given_up_after_the_grace() -> void:
	var beat: PongNetHeartbeat = PongNetHeartbeat.new()
	var limit: Callable = func(_peer: int) -> float: return 1.0
	var keeps: Callable = func(peer: int) -> bool: return peer == 7
	beat.watch(7, 0.0)
	beat.watch(8, 0.0)
	beat.heard(7, 1.0)
	beat.heard(8, 1.0)
	var dead: Array[Array] = beat.overdue(2.5, limit, keeps)
	assert_eq(dead.size(), 2, "both silent 1.5 s")
	assert_true(beat.is_absent(7), "peer 7 keeps its seat: absent, still watched")
	assert_false(beat.is_absent(8), "peer 8 holds none: gone")
	assert_eq(beat.peers(), [7])
	assert_eq(beat.overdue(5.0, limit, keeps), [] as Array[Array], "absent is said once")
	beat.heard(7, 6.0)
	var back: Array[Array] = beat.returned()
	assert_eq(back.size(), 1, "heard again: back")
	assert_eq(back[0][0], 7)
	assert_almost_eq(back[0][1], 5.0, 1e-9, "after 5 s of silence")
	assert_eq(beat.returned(), [] as Array[Array], "said once")
	assert_false(beat.is_absent(7))
	var grace: float = PongNetProtocol.SEAT_GRACE_S
	assert_eq(beat.overdue(7.5, limit, keeps).size(), 1, "silent again")
	assert_eq(beat.given_up(6.0 + grace - 0.01, grace), [] as Array[Array], "within the grace")
	var gone: Array[Array] = beat.given_up(6.0 + grace + 0.01, grace)
	assert_eq(gone.size(), 1, "past the grace: given up")
	assert_eq(beat.peers(), [], "and no longer watched")


func test_a_peer_never_heard_is_not_kept() -> void:
	var beat: PongNetHeartbeat = PongNetHeartbeat.new()
	var keeps: Callable = func(_peer: int) -> bool: return true
	beat.watch(7, 0.0)
	var first: float = PongNetProtocol.FIRST_BEAT_TIMEOUT_S
	var dead: Array[Array] = beat.overdue(first + 0.1, func(_p: int) -> float: return 1.0, keeps)
	assert_eq(dead.size(), 1)
	assert_false(beat.is_absent(7), "a handshake that never finished holds no seat")


func test_the_authority_keeps_an_absent_players_seats_until_it_is_back_or_gone() -> void:
	var authority: PongNetAuthority = PongNetAuthority.new(HOST, PackedInt64Array([HOST, CLIENT]))
	assert_eq(authority.stand_in(CLIENT), PackedInt32Array([1]))
	assert_eq(authority.owners, PackedInt64Array([HOST, HOST]), "the computer plays seat 1")
	assert_eq(authority.kept, {1: CLIENT} as Dictionary[int, int], "kept for the client")
	assert_eq(authority.give_back(CLIENT), PackedInt32Array([1]))
	assert_eq(authority.owners, PackedInt64Array([HOST, CLIENT]), "the client's again")
	assert_eq(authority.give_back(CLIENT), PackedInt32Array(), "once")
	authority.stand_in(CLIENT)
	authority.release_peer(CLIENT)
	assert_true(authority.kept.is_empty(), "gone: the seat is given up")
	assert_eq(authority.give_back(CLIENT), PackedInt32Array(), "nothing to give back")


func test_the_computer_stands_in_and_hands_seat_and_ball_back_on_the_players_return() -> void:
	# The client masters a ball lying in its territory when its packets stop.
	if _open_with_the_ball_at_the_client(FRAME_S) == null:
		return
	var match_node: PongMatch = _play.match_node
	for frame: int in 6:
		_play.frame(FRAME_S)
	assert_eq(match_node.snapshot.territory, 1, "the ball lies in the client's territory")
	_router.sent.clear()
	_play.seats.stand_in(CLIENT)
	assert_eq(_play.authority.owners, PackedInt64Array([HOST, HOST]))
	assert_true(_play.authority.is_master(), "the server took the ball over at once")
	assert_eq(_report.extra["peers_left"][0]["seats"], [1])
	# The client's poses may arrive before the beat that brings it back: no bad messages.
	var pose: PongNetPoseMessage = PongNetPoseMessage.new()
	pose.seat = 1
	pose.avatar = match_node.avatar_of(1)
	pose.normal = Vector3.BACK
	_receive(CLIENT, pose)
	assert_eq(_refused("pose"), 0, "its own seat, kept for it")
	_receive(HOST + 1000, pose)
	assert_eq(_refused("pose"), 1, "not kept for anyone else")
	_router.sent.clear()
	_play.seats.give_back(CLIENT)
	assert_eq(_play.authority.owners, PackedInt64Array([HOST, CLIENT]), "its seat again")
	# What it sent while cut off arrives now: refused, not counted against it.
	pose.seat = 0
	_receive(CLIENT, pose)
	assert_eq(_refused("pose"), 1, "a pose for the host's seat, sent before it knew")
	_receive(HOST + 1000, pose)
	assert_eq(_refused("pose"), 2, "from anyone else it counts")
	var owners: Array[PongNetMessage] = _router.sent_of(PongNetOwnersMessage.SCHEMA_ID)
	assert_eq(owners.size(), 1, "everyone is told")
	var transfers: Array[PongNetMessage] = _router.sent_of(PongNetTransferMessage.SCHEMA_ID)
	assert_eq(transfers.size(), 1, "and the ball in its territory goes back to it")
	var transfer: PongNetTransferMessage = transfers[0]
	assert_eq(transfer.master, CLIENT)
	assert_eq(transfer.kind, PongNetFacts.TransferKind.TAKEOVER)
	assert_eq(_report.extra["seats_back"][0]["seats"], [1])
