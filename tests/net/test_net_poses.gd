extends "res://tests/net/net_play_suite.gd"
## The poses this peer sends are ones the other peers take (PongNetPoses.on_pose's checks),
## from the match's first frame on, before the servo has given a state.

const FRAME_S: float = 1.0 / 60.0
## The paddle reach the receiving peers check a pose's offset against (on_pose's).
const RECEIVER_REACH_M: float = 2.0


func test_our_poses_pass_the_other_peers_checks_from_the_first_frame() -> void:
	if _open_play() == null:
		return
	var court: PongCourt = _play.match_node.court
	# No servo state yet: the match's snapshot is a fresh PongState, its normals zero.
	assert_eq(_play.match_node.snapshot.paddle_normals[0], Vector3.ZERO, "(the test's own check)")
	for frame: int in 3:
		_play.frame(FRAME_S)
		_play.match_node.advance(FRAME_S)
	var poses: Array[Array] = _play.sent_of(&"_pose")
	assert_gt(poses.size(), 0, "our seat's poses")
	for pose: Array in poses:
		var reason: String = PongNetProtocol.check_pose(
			pose[1], court.players, pose[2], pose[3], pose[4], pose[5], court, RECEIVER_REACH_M
		)
		assert_eq(reason, "", "taken by the other peers")
	assert_almost_eq(poses[0][5], PongCourt.forward(0), 1e-6, "at first the seat's own facing")
