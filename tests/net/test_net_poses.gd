extends "res://tests/net/net_play_suite.gd"
## The poses this peer sends are ones the other peers take (their fields within the schema's
## limits, the seat and the avatar this match's), from the match's first frame on, before
## the servo has given a state.

const FRAME_S: float = 1.0 / 60.0


func test_our_poses_pass_the_other_peers_checks_from_the_first_frame() -> void:
	if _open_play() == null:
		return
	var court: PongCourt = _play.match_node.court
	# No servo state yet: the match's snapshot is a fresh PongState, its normals zero.
	assert_eq(_play.match_node.snapshot.paddle_normals[0], Vector3.ZERO, "(the test's own check)")
	for frame: int in 3:
		_play.frame(FRAME_S)
		_play.match_node.advance(FRAME_S)
	var poses: Array[PongNetMessage] = _router.sent_of(PongNetPoseMessage.SCHEMA_ID)
	assert_gt(poses.size(), 0, "our seat's poses")
	for sent: PongNetMessage in poses:
		var pose: PongNetPoseMessage = PongNetPoseMessage.decode(sent.encode())
		assert_not_null(pose, HapticsWireReader.last_error)
		if pose == null:
			continue
		assert_eq(PongNetProtocol.check_seat(pose.seat, court.players), "")
		var limit: Vector3 = PongNetProtocol.position_limit(court)
		assert_eq(PongNetProtocol.check_box(pose.avatar, limit, "avatar"), "")
	var first: PongNetPoseMessage = poses[0]
	assert_almost_eq(first.normal, PongCourt.forward(0), 1e-6, "at first the seat's own facing")


func test_a_pose_moves_the_remote_seat_only_from_its_peer() -> void:
	if _open_play() == null:
		return
	var pose: PongNetPoseMessage = PongNetPoseMessage.new()
	pose.seat = 1
	pose.avatar = _play.match_node.avatar_of(1) + Vector3(0.2, 0.0, 0.0)
	pose.normal = Vector3.BACK
	pose.spin = true
	_receive(HOST + 1000, pose)
	assert_eq(_refused("pose"), 1, "seat 1 is not the sender's")
	_receive(CLIENT, pose)
	var remote: PongNetRemotePlayer = _play.match_node.controllers[1]
	assert_eq(remote.intent.avatar, pose.avatar)
	assert_true(remote.intent.spin)
	assert_eq(_report.poses, 1)
	pose.avatar = Vector3(0.0, 0.0, 50.0)
	_receive(CLIENT, pose)
	assert_eq(_refused("pose"), 2, "an avatar outside this court")
