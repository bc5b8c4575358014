extends "res://tests/net/net_play_suite.gd"
## The host's check of its client master's ball ([PongNetBallCheck], issue 36 item 2), on a
## real stepped match with the real extension: a ball the master's states leave in another
## territory is handed over by the host; a state its simulation cannot reach, the new
## master's first included (checked from the ball the host handed over), is refused, counted
## and never played.

const FRAME_S: float = 1.0 / 60.0
## The client's servo clock at its first state (any clock: only differences count).
const CLIENT_CLOCK_S: float = 40.0


func test_a_ball_the_master_leaves_in_another_territory_is_handed_over_by_the_host() -> void:
	var rest: Variant = _open_with_the_ball_at_the_client(FRAME_S)
	if rest == null:
		return
	var epoch: int = _play.authority.epoch
	assert_eq(_play.authority.master_peer, CLIENT, "the client is the master")
	# The client's ball lies still just across the border, in the host's territory (where a
	# new master's ball may settle), and it asks for no hand-off.
	var there: Vector3 = rest
	there.z = -signf(there.z) * 0.3
	assert_eq(_play.match_node.court.territory_at(there), 0, "the host's territory")
	var before: int = _router.sent_of(PongNetTransferMessage.SCHEMA_ID).size()
	var handed_at: int = -1
	for frame: int in 90:
		_receive(CLIENT, _state(epoch, frame, there, Vector3.ZERO))
		_play.frame(FRAME_S)
		if _router.sent_of(PongNetTransferMessage.SCHEMA_ID).size() > before:
			handed_at = frame
			break
	var waited_s: float = handed_at * FRAME_S
	assert_gt(handed_at, -1, "the host handed the ball over")
	assert_true(
		waited_s >= PongNetBallCheck.LEFT_BEHIND_S - 0.1,
		"not before the master had its second to ask (%.2f s)" % waited_s
	)
	var sent: Array[PongNetMessage] = _router.sent_of(PongNetTransferMessage.SCHEMA_ID)
	var handoff: PongNetTransferMessage = sent[-1]
	assert_eq(handoff.kind, PongNetFacts.TransferKind.HANDOFF)
	assert_eq([handoff.epoch, handoff.territory, handoff.master], [epoch + 1, 0, HOST])
	assert_almost_eq(handoff.position.distance_to(there), 0.0, 0.01, "where its states left it")
	assert_eq(_play.authority.master_peer, HOST, "the host simulates it now")
	assert_eq(_refused("ball state"), 0, "an honest still ball is no bad state")


func test_a_state_the_hosts_simulation_cannot_reach_is_refused_and_never_played() -> void:
	var rest: Variant = _open_with_the_ball_at_the_client(FRAME_S)
	if rest == null:
		return
	var epoch: int = _play.authority.epoch
	var at: Vector3 = rest
	# Past the first second, in which a new master's ball may still be settling.
	var settled: int = ceili(PongServoFacts.PONG_WITNESS_SETTLE_S / FRAME_S) + 2
	for frame: int in settled:
		_receive(CLIENT, _state(epoch, frame, at, Vector3.ZERO))
		_play.frame(FRAME_S)
	var taken: int = _play.ball.buffer.to_dict()["received"]
	# The next state has the ball 2 m away, 17 ms later, lying as still as before.
	_receive(CLIENT, _state(epoch, settled, at + Vector3(0.0, 0.0, 2.0), Vector3.ZERO))
	assert_eq(_refused("ball state"), 1, "refused and counted")
	assert_eq(_play.ball.buffer.to_dict()["received"], taken, "never taken into the play")
	assert_eq(_play.ball_check.verdicts.get("unreachable", 0), 1)
	# The client's honest stream goes on being taken, checked from the last state kept.
	_receive(CLIENT, _state(epoch, settled + 1, at, Vector3.ZERO))
	assert_eq(_refused("ball state"), 1)
	assert_eq(_play.ball.buffer.to_dict()["received"], taken + 1)


func test_a_new_masters_ball_far_from_the_one_handed_over_is_refused_from_its_first_state() -> void:
	var rest: Variant = _open_with_the_ball_at_the_client(FRAME_S)
	if rest == null:
		return
	var epoch: int = _play.authority.epoch
	var handed: Vector3 = rest
	# Handed over at rest in its territory, the client streams a still ball deep in the host's
	# (the issue's forger, as the first state of a new epoch used to be taken as it was).
	var there: Vector3 = handed
	there.z = -there.z
	for frame: int in 20:
		_receive(CLIENT, _state(epoch, frame, there, Vector3.ZERO))
		_play.frame(FRAME_S)
	assert_eq(_refused("ball state"), 20, "every state refused and counted")
	assert_eq(_play.ball.buffer.to_dict()["received"], 0, "none played")
	# Its honest ball where it was handed over is taken.
	_receive(CLIENT, _state(epoch, 20, handed, Vector3.ZERO))
	assert_eq(_refused("ball state"), 20)
	assert_eq(_play.ball.buffer.to_dict()["received"], 1)


# The client's ball state number [param index] of [param epoch], a frame apart on its clock.
func _state(epoch: int, index: int, position: Vector3, velocity: Vector3) -> PongNetBallMessage:
	var state: PongNetBallMessage = PongNetBallMessage.new()
	state.epoch = epoch
	state.seq = index + 1
	state.time_s = CLIENT_CLOCK_S + index * FRAME_S
	state.position = position
	state.velocity = velocity
	return state
