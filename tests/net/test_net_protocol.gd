extends TestSuite
## The checks every received message passes: its fields against the schema's limits as it is
## decoded (types, finiteness, ranges, sizes), then against this match's court.

const PongTestCourt := preload("res://tests/pong/pong_test_court.gd")

var _court: PongCourt = null


func before_each() -> void:
	_court = PongTestCourt.make()


func _ball(overrides: Dictionary) -> PongNetBallMessage:
	var state: PongNetBallMessage = PongNetBallMessage.new()
	state.epoch = 1
	state.seq = 2
	state.time_s = 3.5
	state.position = Vector3(0, 1, -1)
	state.velocity = Vector3(0, 0, 5)
	for key: String in overrides:
		state.set(key, overrides[key])
	return state


# Why the ball state of [param overrides] is refused: by its decode, or against the court.
func _why(overrides: Dictionary) -> String:
	var state: PongNetBallMessage = PongNetBallMessage.decode(_ball(overrides).encode())
	if state == null:
		return HapticsWireReader.last_error
	return PongNetProtocol.check_ball(state.position, state.velocity, state.spin, _court, 120.0)


func test_a_good_ball_state_passes() -> void:
	assert_eq(_why({}), "")


func test_bad_ball_states_are_refused_with_the_reason() -> void:
	assert_true(_why({"epoch": -1}).contains("epoch"), _why({"epoch": -1}))
	assert_true(_why({"seq": -1}).contains("seq: -1 is outside"), _why({"seq": -1}))
	assert_true(_why({"time_s": NAN}).contains("time_s: not finite"))
	assert_true(_why({"position": Vector3(0, 1, 99)}).contains("position"))
	assert_true(_why({"position": Vector3(0, 1, 101)}).contains("position: length"))
	assert_true(_why({"velocity": Vector3(INF, 0, 0)}).contains("not finite"))
	var fast: float = _court.max_ball_speed * PongNetProtocol.SPEED_MARGIN + 0.1
	assert_true(_why({"velocity": Vector3(0, 0, fast)}).contains("velocity"))
	assert_true(_why({"spin": Vector3(500, 0, 0)}).contains("spin"))
	assert_true(_why({"leg_ms": 10001}).contains("leg_ms: 10001 is outside"))


func test_the_bytes_of_a_state_are_its_layout_id_then_its_fields() -> void:
	var bytes: PackedByteArray = _ball({}).encode()
	assert_eq(bytes.decode_u32(0), PongNetBallMessage.SCHEMA_ID)
	# epoch u32, seq i64, time f64, three vec3f, leg u16.
	assert_eq(bytes.size(), 4 + 4 + 8 + 8 + 3 * 12 + 2)
	assert_null(PongNetBallMessage.decode(bytes.slice(0, bytes.size() - 1)))
	assert_true(HapticsWireReader.last_error.contains("end early"), HapticsWireReader.last_error)
	assert_null(PongNetPoseMessage.decode(bytes), "another message's layout")
	assert_true(HapticsWireReader.last_error.contains("is not this one"))


func test_poses_are_checked_for_seat_ranges_and_a_unit_normal() -> void:
	var pose: PongNetPoseMessage = PongNetPoseMessage.new()
	pose.seat = 1
	pose.avatar = Vector3(0, 0.9, -1.8)
	pose.offset = Vector3(0.1, 0, 0)
	pose.normal = Vector3.BACK
	assert_not_null(PongNetPoseMessage.decode(pose.encode()), HapticsWireReader.last_error)
	assert_true(PongNetProtocol.check_seat(pose.seat, 2).is_empty())
	assert_true(PongNetProtocol.check_seat(2, 2).contains("seat 2"))
	pose.normal = Vector3(0, 0, 0.5)
	assert_null(PongNetPoseMessage.decode(pose.encode()))
	assert_true(HapticsWireReader.last_error.contains("normal: length 0.5 is below 0.99"))
	pose.normal = Vector3.BACK
	pose.offset = Vector3(0, 0, 3.5)
	assert_null(PongNetPoseMessage.decode(pose.encode()))
	assert_true(HapticsWireReader.last_error.contains("offset"), HapticsWireReader.last_error)


func test_names_must_be_short_non_empty_strings() -> void:
	assert_eq(PongNetProtocol.check_name("Ada"), "")
	assert_ne(PongNetProtocol.check_name("   "), "")
	assert_ne(PongNetProtocol.check_name("x".repeat(25)), "", "more than 24 characters")
	var hello: PongNetHelloMessage = PongNetHelloMessage.new()
	hello.name = "x".repeat(65535)
	assert_null(PongNetHelloMessage.decode(hello.encode()), "an oversized name")
	assert_true(HapticsWireReader.last_error.contains("65535 bytes of text, at most 96"))


func test_an_identity_is_up_to_32_hex_digits_and_each_peer_draws_its_own() -> void:
	var drawn: String = PongNetRejoins.new(null).identity
	assert_eq(drawn.length(), 32)
	assert_true(PongNetProtocol.is_identity(drawn), drawn)
	assert_ne(PongNetRejoins.new(null).identity, drawn, "128 random bits each")
	for bad: String in ["", "+abc", "-abc", "xyz", "a".repeat(33), "0x12"]:
		assert_false(PongNetProtocol.is_identity(bad), bad)
	var hello: PongNetHelloMessage = PongNetHelloMessage.new()
	hello.identity = "f".repeat(33)
	assert_null(PongNetHelloMessage.decode(hello.encode()), "an oversized identity")


func test_an_identity_lasts_in_its_file_and_a_bad_file_gets_a_new_one() -> void:
	var path: String = "user://test_identity_%d.txt" % Time.get_ticks_usec()
	var first: String = PongNetRejoins.lasting(path)
	assert_true(PongNetProtocol.is_identity(first), first)
	assert_eq(PongNetRejoins.lasting(path), first, "the same after a restart")
	var file: FileAccess = FileAccess.open(path, FileAccess.WRITE)
	file.store_string("not an identity")
	file.close()
	var fresh: String = PongNetRejoins.lasting(path)
	assert_true(PongNetProtocol.is_identity(fresh) and fresh != first, fresh)
	assert_eq(FileAccess.get_file_as_string(path), fresh, "written for the next start")
	DirAccess.remove_absolute(ProjectSettings.globalize_path(path))


func test_a_resumed_match_takes_each_seats_health_within_the_start() -> void:
	var rules: PongRules = PongRules.new(99, 2)
	rules.resume(PackedInt32Array([40, 120, 7]))
	assert_eq([rules.get_health(0), rules.get_health(1)], [40, 99], "clamped; a third ignored")
	assert_false(rules.is_over())


func test_the_mine_limits_are_the_games() -> void:
	assert_eq(PongNetFacts.NET_MINES_PER_SEAT, PongMines.KINDS.size(), "one of each kind")
	assert_eq(
		PongNetFacts.NET_MAX_MINES,
		PongNetFacts.NET_MINES_PER_SEAT * PongServoFacts.PONG_MAX_PLAYERS,
		"every seat's at once"
	)


func test_channels_are_distinct_and_the_streams_have_their_own() -> void:
	var channels: Array[int] = [
		PongNetFacts.NET_CHANNEL_BALL,
		PongNetFacts.NET_CHANNEL_POSE,
		PongNetFacts.NET_CHANNEL_RELIABLE,
		PongNetFacts.NET_CHANNEL_BEAT,
	]
	for i: int in channels.size():
		assert_gt(channels[i], 0, "0 is Godot's own, the handshake's")
		assert_eq(channels.count(channels[i]), 1, "channel %d is one stream's" % channels[i])
	assert_eq(PongNetBallMessage.CHANNEL, PongNetFacts.NET_CHANNEL_BALL)
	assert_eq(PongNetPoseMessage.CHANNEL, PongNetFacts.NET_CHANNEL_POSE)
	assert_eq(PongNetHelloMessage.CHANNEL, PongNetFacts.NET_CHANNEL_HANDSHAKE)


func test_nothing_on_the_heartbeat_channel_can_hold_a_beat_back() -> void:
	# ENet hands an unreliable packet over only after the reliable ones sent before it on its
	# channel: a reliable stall notice lost on the rough path held the beats for seconds.
	var unreliable: MultiplayerPeer.TransferMode = MultiplayerPeer.TRANSFER_MODE_UNRELIABLE_ORDERED
	assert_eq(PongNetBeatMessage.CHANNEL, PongNetFacts.NET_CHANNEL_BEAT)
	assert_eq(PongNetStallMessage.CHANNEL, PongNetFacts.NET_CHANNEL_BEAT)
	assert_eq(PongNetBeatMessage.TRANSFER_MODE, unreliable)
	assert_eq(
		PongNetStallMessage.TRANSFER_MODE, unreliable, "ordered, so no older beat overtakes it"
	)
	assert_gt(PongNetHeartbeat.SETTLE_FRAMES, 1, "repeated, so one loss does not lose it")
