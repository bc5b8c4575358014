extends "res://tests/net/net_play_suite.gd"
## A client's view of a seat the server stood in for: the player's first poses on their
## return travel apart from the owners message that gives the seat back, and can reach
## another client first (a 4-player match on the 150 ms path: client1 counted a bad pose
## from client3, back after 1.2 s of silence). Such a pose is refused and not counted
## against the player; a pose for a seat that was never theirs still is.

## This client watches seat 1, whose player (BACK) goes silent and comes back.
const ME: int = 42
const BACK: int = 77
const OTHER: int = 91


func test_a_returning_player_s_pose_that_overtakes_the_owners_message_is_not_counted() -> void:
	if _open_play(ME, PackedInt64Array([HOST, BACK])) == null:
		return
	var authority: PongNetAuthority = _play.authority
	_owners([HOST, HOST])
	assert_eq(authority.taken_from, {1: BACK}, "seat 1 taken from its silent player")
	var remote: PongNetRemotePlayer = _play.match_node.controllers[1]
	var early: PongNetPoseMessage = _pose(1, 0.2)
	_receive(BACK, early)
	assert_eq(_refused("pose"), 0, "the player coming back: refused, not counted")
	assert_ne(remote.intent.avatar, early.avatar, "and not applied")
	_receive(OTHER, early)
	assert_eq(_refused("pose"), 1, "a seat that was never theirs: counted")
	_owners([HOST, BACK])
	assert_eq(authority.taken_from, {}, "given back")
	var back: PongNetPoseMessage = _pose(1, 0.3)
	_receive(BACK, back)
	assert_eq(remote.intent.avatar, back.avatar, "the seat's poses are theirs again")
	assert_eq(_refused("pose"), 1)


func test_a_seat_given_to_another_player_forgets_whom_it_was_taken_from() -> void:
	if _open_play(ME, PackedInt64Array([HOST, BACK])) == null:
		return
	_owners([HOST, HOST])
	_owners([HOST, OTHER])
	assert_eq(_play.authority.taken_from, {}, "seat 1 has a player again")
	_receive(BACK, _pose(1, 0.2))
	assert_eq(_refused("pose"), 1, "its old player's word counts again")


func _owners(owners: Array[int]) -> void:
	var message: PongNetOwnersMessage = PongNetOwnersMessage.new()
	message.owners = PackedInt64Array(owners)
	_receive(HOST, message)


func _pose(seat: int, dx: float) -> PongNetPoseMessage:
	var pose: PongNetPoseMessage = PongNetPoseMessage.new()
	pose.seat = seat
	pose.avatar = _play.match_node.avatar_of(seat) + Vector3(dx, 0.0, 0.0)
	pose.normal = PongCourt.forward(seat)
	return pose
