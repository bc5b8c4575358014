extends "res://tests/net/net_play_suite.gd"
## The server referees while it follows: a ball its master says is at rest is served again
## after the stall time, though the server's own copy of it, carried on from late states,
## never quite comes to rest.

const FRAME_S: float = 1.0 / 60.0
## How late the master's states arrive here, seconds (one 150 ms leg).
const LATE_S: float = 0.15


func test_the_server_serves_again_when_its_masters_ball_has_stalled() -> void:
	if _open_play() == null:
		return
	_play.stepped = true
	_play.ball.stepped = true
	var match_node: PongMatch = _play.match_node
	# As in a networked match: the master's word on floor bounces, not this servo's.
	match_node.rules_from_events = false
	var court: PongCourt = match_node.court
	var rest: Vector3 = Vector3(0.3, court.ball_radius, -court.half_length * 0.6)
	if court.territory_at(rest) != 1:
		rest.z = -rest.z
	assert_eq(court.territory_at(rest), 1, "a spot in the client's territory")
	# The referee's opening serve first.
	for frame: int in 240:
		_play.frame(FRAME_S)
		if not _serves().is_empty():
			break
	assert_eq(_serves().size(), 1, "the opening serve")
	var epoch: int = _play.authority.epoch + 1
	var handoff: PongNetTransferMessage = PongNetTransferMessage.new()
	handoff.epoch = epoch
	handoff.kind = PongNetFacts.TransferKind.HANDOFF
	handoff.territory = 1
	handoff.master = CLIENT
	handoff.position = rest
	_receive(HOST, handoff)
	assert_false(_play.authority.is_master(), "the client masters the ball")
	_router.sent.clear()
	var served: bool = false
	var seconds: float = PongReferee.STALL_SECONDS + 1.0
	for frame: int in roundi(seconds / FRAME_S):
		# The first state sets the clock (no delay); the others are a leg late.
		var sent_at: float = Time.get_ticks_usec() / 1e6 - (LATE_S if frame > 0 else 0.0)
		var state: PongNetBallMessage = PongNetBallMessage.new()
		state.epoch = epoch
		state.seq = frame + 1
		state.time_s = sent_at
		state.position = rest
		state.leg_ms = 150
		_receive(CLIENT, state)
		_play.frame(FRAME_S)
		if not _serves().is_empty():
			served = true
			assert_gt(frame * FRAME_S, PongReferee.STALL_SECONDS - 0.1, "not before the stall time")
			break
	assert_true(served, "served again within %.1f s" % seconds)


func _serves() -> Array[PongNetTransferMessage]:
	var serves: Array[PongNetTransferMessage] = []
	for sent: PongNetMessage in _router.sent_of(PongNetTransferMessage.SCHEMA_ID):
		var transfer: PongNetTransferMessage = sent
		if transfer.kind == PongNetFacts.TransferKind.SERVE:
			serves.append(transfer)
	return serves
