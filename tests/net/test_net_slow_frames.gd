extends "res://tests/net/net_play_suite.gd"
## A window drawing 10 frames a second hosts: its servo runs on at 1 kHz between frames, and
## the game reads the servo's state and events once a frame, after its network play has
## acted on the state read the frame before. A transfer applied in a frame must not be
## judged by what the servo did before it (a person's match had a serve handed back as the
## dead ball it replaced, and the new master's claim of its follower copy's bounce refused).
## The servo is stepped by hand in the real-time order: its ticks, the play, the match.

const FRAME_S: float = 0.1
const TICKS_PER_FRAME: int = roundi(FRAME_S / PongServo.TICK_S)
## How late the master's states arrive here, seconds (one 150 ms leg).
const LATE_S: float = 0.15


func test_a_serve_is_not_handed_back_as_the_ball_it_replaced() -> void:
	var opened: Variant = _open_with_the_ball_at_the_client(1.0 / 60.0)
	if opened == null:
		return
	var rest: Vector3 = opened
	_play.stepped = false
	var epoch: int = _play.authority.epoch
	_router.sent.clear()
	var served_at: int = -1
	var seconds: float = PongReferee.STALL_SECONDS + 3.0
	for frame: int in roundi(seconds / FRAME_S):
		if served_at < 0:
			var state: PongNetBallMessage = PongNetBallMessage.new()
			state.epoch = epoch
			state.seq = frame + 1
			state.time_s = Time.get_ticks_usec() / 1e6 - (LATE_S if frame > 0 else 0.0)
			state.position = rest
			state.leg_ms = 150
			_receive(CLIENT, state)
		_real_time_frame()
		if served_at < 0 and not _transfers(PongNetFacts.TransferKind.SERVE).is_empty():
			served_at = frame
		if served_at >= 0 and frame > served_at + 10:
			break
	assert_gt(served_at, -1, "the dead ball was served again")
	for handoff: PongNetTransferMessage in _transfers(PongNetFacts.TransferKind.HANDOFF):
		assert_gt(
			handoff.position.distance_to(rest),
			0.5,
			"a hand-off after the serve gives the served ball, not the dead one at %s" % rest
		)


func test_a_new_masters_servo_events_from_before_the_transfer_are_not_its_own() -> void:
	var opened: Variant = _open_with_the_ball_at_the_client(1.0 / 60.0)
	if opened == null:
		return
	var rest: Vector3 = opened
	_play.stepped = false
	var match_node: PongMatch = _play.match_node
	var court: PongCourt = match_node.court
	var floors: Array[PongEvent] = []
	var note_floor: Callable = func(event: PongEvent) -> void:
		if event.type == PongServoFacts.PongEventType.FLOOR:
			floors.append(event)
	match_node.event_seen.connect(note_floor)
	var epoch: int = _play.authority.epoch
	var health: Array[int] = _health()
	_router.sent.clear()
	# The client's ball falls near the middle line in its own territory: this peer's copy
	# bounces on the floor there during the ticks before the client's hand-off arrives.
	var falling: PongNetBallMessage = PongNetBallMessage.new()
	falling.epoch = epoch
	falling.seq = 1
	falling.time_s = Time.get_ticks_usec() / 1e6
	falling.position = Vector3(0.3, court.ball_radius + 0.3, 0.15 * signf(rest.z))
	falling.velocity = Vector3(0.0, -3.0, 0.0)
	falling.leg_ms = 0
	_receive(CLIENT, falling)
	_real_time_frame()
	for frame: int in 20:
		PongServo.shared().step_ticks(TICKS_PER_FRAME)
		if not floors.is_empty() or _servo_floor_bounced(court):
			break
		_play.frame(FRAME_S)
		match_node.advance(FRAME_S)
	# The servo has bounced the copy since the last frame read it; the hand-off arrives now.
	var request: PongNetHandOffMessage = PongNetHandOffMessage.new()
	request.epoch = epoch
	request.territory = 0
	request.position = Vector3(0.3, 0.3, -0.05 * signf(rest.z))
	request.velocity = Vector3(0.0, 1.5, -0.5 * signf(rest.z))
	_receive(CLIENT, request)
	_play.frame(FRAME_S)
	assert_true(_play.authority.is_master(), "the hand-off made this peer the master")
	match_node.advance(FRAME_S)
	match_node.event_seen.disconnect(note_floor)
	assert_false(floors.is_empty(), "the copy bounced before the transfer (the case tested)")
	for event: PongEvent in floors:
		assert_eq(event.territory, 1, "the copy bounced in the client's territory")
	assert_eq(_health(), health, "no one lost a point to the follower copy's bounce")
	assert_eq(
		_router.sent_of(PongNetFloorHurtMessage.SCHEMA_ID).size(), 0, "no floor hurt was sent"
	)


# One frame of a window: the servo's ticks since the last, the play on the state the match
# read the frame before, then the match reads the servo's state and events.
func _real_time_frame() -> void:
	PongServo.shared().step_ticks(TICKS_PER_FRAME)
	_play.frame(FRAME_S)
	_play.match_node.advance(FRAME_S)


# Whether the servo's ball is rising near the floor: it bounced since the last look.
func _servo_floor_bounced(court: PongCourt) -> bool:
	var state: PongState = PongServo.shared().get_state()
	return state.ball_velocity.y > 0.0 and state.ball_position.y < court.ball_radius + 0.3


func _health() -> Array[int]:
	var out: Array[int] = []
	for seat: int in 2:
		out.append(_play.match_node.rules.get_health(seat))
	return out


func _transfers(kind: PongNetFacts.TransferKind) -> Array[PongNetTransferMessage]:
	var out: Array[PongNetTransferMessage] = []
	for sent: PongNetMessage in _router.sent_of(PongNetTransferMessage.SCHEMA_ID):
		var transfer: PongNetTransferMessage = sent
		if transfer.kind == kind:
			out.append(transfer)
	return out
