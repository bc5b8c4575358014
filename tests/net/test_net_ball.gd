extends TestSuite
## A follower's ball in the real servo: a correction that would put it under the floor or
## past a wall (a blend pointing down as the ball lands, an extrapolation beyond the back
## wall of a four-player court) is kept inside the court, where the servo takes it, instead
## of being refused with an engine error.

const PongTestScreen := preload("res://tests/pong/pong_test_screen.gd")

var _pong: PongScreen = null


func after_each() -> void:
	if _pong != null and is_instance_valid(_pong):
		_pong.queue_free()
	_pong = null
	await wait_process_frames(2)


func test_a_correction_outside_the_court_lands_inside_it() -> void:
	for players: int in [2, 4]:
		var match_node: PongMatch = _open(players)
		if match_node == null:
			return
		var court: PongCourt = match_node.court
		var ball: PongNetBall = PongNetBall.new()
		ball.stepped = true
		ball.court = court
		var outside: Vector3 = Vector3(court.half_width + 0.5, -0.2, -court.half_length - 0.44)
		ball.put(outside, Vector3(0.0, 0.0, -1.0), Vector3.ZERO)
		match_node.run_until(func() -> bool: return false, 0.002)
		var at: Vector3 = Haptics.pong.get_state().ball_position
		var r: float = court.ball_radius
		assert_almost_eq(at.y, r, 0.05, "%d players: on the floor, not under it" % players)
		assert_lt(absf(at.x), court.half_width, "%d players: inside the side wall" % players)
		assert_lt(absf(at.z), court.half_length, "%d players: inside the back wall" % players)
		assert_gt(absf(at.z), court.half_length - 0.2, "%d players: where it was sent" % players)
		_pong.queue_free()
		_pong = null
		await wait_process_frames(2)


func _open(players: int) -> PongMatch:
	if not assert_true(Haptics.pong.is_available(), "the extension has the Pong renderer"):
		return null
	_pong = PongTestScreen.stepped(PongMatch.Mode.DEMO, players)
	add_child(_pong)
	return _pong.match_node
