extends "res://tests/net/net_play_suite.gd"
## The router, the one way messages come and go: every message's bytes decode to what was
## encoded, with the facts the schema gives it (channel, transfer mode, who sends and takes
## it); bytes that decode to nothing, or a message from or to the wrong peer, are one bad
## message of their sender each, never an engine error, on one peer of a real stepped match.


func test_bad_bytes_are_bad_messages_of_their_sender_not_engine_errors() -> void:
	# The runner fails a test on any engine error: none of these may print one.
	var play: PongNetPlay = _open_play()
	if play == null:
		return
	var owners: PongNetOwnersMessage = PongNetOwnersMessage.new()
	owners.owners = PackedInt64Array([CLIENT, CLIENT])
	var good: PackedByteArray = owners.encode()
	var unknown: PackedByteArray = good.duplicate()
	unknown.encode_u32(0, 0xDEADBEEF)
	var hello: PongNetHelloMessage = PongNetHelloMessage.new()
	hello.name = "x".repeat(65535)
	var nan_ball: PongNetBallMessage = PongNetBallMessage.new()
	nan_ball.velocity = Vector3(NAN, 0.0, 0.0)
	var cases: Dictionary[String, PackedByteArray] = {
		"no layout id": PackedByteArray([1, 2]),
		"unknown layout": unknown,
		"cut off": good.slice(0, good.size() - 1),
		"bytes left over": good + PackedByteArray([0]),
		"NaN": nan_ball.encode(),
		"a 64 KiB name": hello.encode(),
		"only the server sends it": good,
	}
	var counted: int = 0
	for what: String in cases:
		_router.receive(CLIENT, cases[what])
		counted += 1
		assert_eq(play.session.budget.count_of(CLIENT), counted, what)
	assert_eq(play.authority.owners, PackedInt64Array([HOST, CLIENT]), "owners unchanged")
	assert_eq(_refused("message"), 2, "no layout id, an unknown one")
	assert_eq(_refused("owners"), 3, str(_report.refused))
	assert_eq(_refused("ball state") + _refused("hello"), 2, str(_report.refused))
	# A client takes no message only the server takes.
	play.session.is_server = false
	var claim: PongNetFloorClaimMessage = PongNetFloorClaimMessage.new()
	_router.receive(HOST, claim.encode())
	assert_eq(_refused("floor claim"), 1, "on a client")
	# The sender's own messages are good again: the server's owners are taken.
	owners.owners = PackedInt64Array([HOST, HOST])
	_receive(HOST, owners)
	assert_eq(play.authority.owners, PackedInt64Array([HOST, HOST]))


func test_every_message_decodes_what_it_encodes_and_names_its_channel() -> void:
	var decoders: Dictionary[int, Callable] = PongNetFacts.message_decoders()
	assert_eq(decoders.size(), PongNetFacts.MESSAGE_LABELS.size())
	var beat: PongNetBeatMessage = PongNetBeatMessage.new()
	beat.wall_s = 1.8e9 + 0.123456
	var beat_back: PongNetBeatMessage = decoders[PongNetBeatMessage.SCHEMA_ID].call(beat.encode())
	assert_eq(
		beat_back.wall_s if beat_back != null else 0.0, beat.wall_s, "a beat's stamp, to 1 us"
	)
	assert_false(decoders.has(PongNetForward.ID), "a forward's id is no message's")
	for id: int in [PongNetReliable.DATA_ID, PongNetReliable.ACK_ID]:
		assert_false(decoders.has(id) or id == PongNetForward.ID, "%08x is taken once" % id)
	var pose: PongNetPoseMessage = PongNetPoseMessage.new()
	pose.seat = 1
	pose.normal = Vector3.BACK
	pose.gun = true
	var back: PongNetPoseMessage = decoders[PongNetPoseMessage.SCHEMA_ID].call(pose.encode())
	assert_not_null(back, HapticsWireReader.last_error)
	if back != null:
		assert_eq([back.seat, back.normal, back.gun, back.spin], [1, Vector3.BACK, true, false])
	assert_eq(pose.channel(), PongNetFacts.NET_CHANNEL_POSE)
	assert_eq(pose.transfer_mode(), MultiplayerPeer.TRANSFER_MODE_UNRELIABLE_ORDERED)
	var ball: PongNetBallMessage = PongNetBallMessage.new()
	assert_eq(ball.transfer_mode(), MultiplayerPeer.TRANSFER_MODE_UNRELIABLE, "unsequenced")
	assert_true(PongNetTransferMessage.new().from_server())
	assert_true(PongNetHandOffMessage.new().to_server())
	assert_eq(PongNetHelloMessage.new().channel(), PongNetFacts.NET_CHANNEL_HANDSHAKE)


func test_a_match_message_between_matches_is_dropped_quietly() -> void:
	var play: PongNetPlay = _open_play()
	if play == null:
		return
	play.end()
	var pose: PongNetPoseMessage = PongNetPoseMessage.new()
	pose.seat = 1
	pose.normal = Vector3.BACK
	_receive(CLIENT, pose)
	assert_eq(play.session.budget.count_of(CLIENT), 0, "nobody handles it: no bad message")
	assert_eq(_report.poses, 0)


func test_a_flood_of_bad_packets_is_counted_not_logged_one_by_one() -> void:
	var play: PongNetPlay = _open_play()
	if play == null:
		return
	# The runner fails the test on any engine error: a thousand packets print two lines (the
	# first bad message and the disconnect), both our own.
	for i: int in 1000:
		_router.receive(CLIENT, PackedByteArray([i & 0xFF, 0xBE, 0xAD, 0xDE, 0]))
	assert_eq(play.session.budget.count_of(CLIENT), 1000)
	assert_eq(_refused("message"), 1000)


func test_the_server_forwards_what_it_accepted_and_a_client_takes_forwards_from_it_only() -> void:
	var play: PongNetPlay = _open_play()
	if play == null:
		return
	var pose: PongNetPoseMessage = PongNetPoseMessage.new()
	pose.seat = 1
	pose.normal = Vector3.BACK
	pose.avatar = play.match_node.avatar_of(1)
	_router.receive(CLIENT, pose.encode())
	assert_eq(_router.forwards.size(), 1, "the client's pose of its own seat goes on")
	if _router.forwards.size() == 1:
		assert_eq(_router.forwards[0][0], CLIENT, "as the client's")
	pose.seat = 0
	_router.receive(CLIENT, pose.encode())
	assert_eq(_refused("pose"), 1, "a pose of the host's seat is refused")
	assert_eq(_router.forwards.size(), 1, "and never forwarded")
	# A client: a forward from its server is its origin's message (a pose of a seat that is
	# not the origin's is that origin's bad message, not the server's).
	play.session.is_server = false
	pose.seat = 1
	_router.receive(HOST, PongNetForward.wrap(77, pose.encode()))
	assert_eq(play.session.budget.count_of(77), 1, "judged as peer 77's")
	assert_eq(play.session.budget.count_of(HOST), 0, "not the server's")
	for what: String in ["from a client", "from the server itself", "a forward in a forward"]:
		var sender: int = CLIENT if what == "from a client" else HOST
		var origin: int = HOST if what == "from the server itself" else 77
		var inner: PackedByteArray = pose.encode()
		if what == "a forward in a forward":
			inner = PongNetForward.wrap(78, inner)
		var before: int = play.session.budget.count_of(sender)
		_router.receive(sender, PongNetForward.wrap(origin, inner))
		assert_eq(play.session.budget.count_of(sender), before + 1, what)
	assert_eq(_refused("forward"), 3, str(_report.refused))
