extends "res://tests/pong/pong_screen_suite.gd"
## A follower's ball in the real servo: a correction that would put it under the floor or
## past a wall (a blend pointing down as the ball lands, an extrapolation beyond the back
## wall of a four-player court) is kept inside the court, where the servo takes it, instead
## of being refused with an engine error; a transfer glides the ball over (no jump) unless a
## paddle touched it since the transfer's state was sent; a serve is put at once.

const PongTestScreen := preload("res://tests/pong/pong_test_screen.gd")
const ScriptedBallPath := preload("res://tests/net/scripted_ball_path.gd")


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
		var at: Vector3 = PongServo.shared().get_state().ball_position
		var r: float = court.ball_radius
		assert_almost_eq(at.y, r, 0.05, "%d players: on the floor, not under it" % players)
		assert_lt(absf(at.x), court.half_width, "%d players: inside the side wall" % players)
		assert_lt(absf(at.z), court.half_length, "%d players: inside the back wall" % players)
		assert_gt(absf(at.z), court.half_length - 0.2, "%d players: where it was sent" % players)
		await _free_pong()


func test_a_transfer_glides_the_ball_over_unless_our_paddle_touched_it_since() -> void:
	var match_node: PongMatch = _open(2)
	if match_node == null:
		return
	var court: PongCourt = match_node.court
	ScriptedBallPath.no_paddles()
	var ball: PongNetBall = PongNetBall.new()
	ball.stepped = true
	ball.court = court
	var here: Vector3 = Vector3(0.0, 1.5, 1.0)
	var there: Vector3 = Vector3(0.8, 1.5, -1.0)  # 2.15 m away, in the other territory.
	ball.put(here, Vector3.ZERO, Vector3.ZERO)
	PongServo.shared().step_ticks(1)
	ball.transfer(false, [there, Vector3(0, 1, 0), Vector3.ZERO], 0.05, 10.0)
	PongServo.shared().step_ticks(1)
	var state: PongState = PongServo.shared().get_state()
	var moved: float = (state.ball_position - here).length()
	assert_gt(moved, 0.001, "on its way")
	assert_lt(moved, 0.05, "no jump: a glide")
	assert_almost_eq(state.ball_velocity.y, 1.0, 0.01, "the velocity taken at once")
	assert_eq(state.territory, 1, "the corrected ball's territory")
	PongServo.shared().step_ticks(300)
	state = PongServo.shared().get_state()
	var predictor: PongPredictor = PongPredictor.new(court)
	var target: Array[Vector3] = PongNetSmoother.extrapolate(
		predictor, there, Vector3(0, 1, 0), court.gravity, 0.301
	)
	assert_lt((state.ball_position - target[0]).length(), 0.03, "on the master's flight")

	# Our paddle touched the ball at 20.0 s: a state sent before is not news to us.
	ball.touched(20.0)
	var before: Vector3 = state.ball_position
	ball.transfer(false, [here, Vector3.ZERO, Vector3.ZERO], 0.1, 20.05)
	PongServo.shared().step_ticks(1)
	state = PongServo.shared().get_state()
	assert_lt((state.ball_position - before).length(), 0.01, "kept: it only flew on")
	assert_eq(ball.ignored, 1)
	ball.transfer(false, [here, Vector3.ZERO, Vector3.ZERO], 0.01, 20.05)
	PongServo.shared().step_ticks(1)
	assert_lt(
		(PongServo.shared().get_state().ball_position - here).length(),
		(state.ball_position - here).length() - 0.005,
		"a state sent after the touch corrects it"
	)
	# Our pose takes 0.3 s to reach the master: a state sent 0.2 s after our touch, carried
	# to now, would put back under our paddle a ball we had just returned.
	PongServo.shared().step_ticks(300)  # The last correction glided in.
	ball.touched(25.0, 0.3)
	state = PongServo.shared().get_state()
	var flown: Array[Vector3] = PongNetSmoother.extrapolate(
		predictor, state.ball_position, state.ball_velocity, court.gravity, 20 * PongServo.TICK_S
	)
	ball.transfer(false, [here, Vector3.ZERO, Vector3.ZERO], 0.1, 25.3)
	PongServo.shared().step_ticks(20)
	state = PongServo.shared().get_state()
	assert_lt((state.ball_position - flown[0]).length(), 0.005, "kept: the master did not know")
	assert_eq(ball.ignored, 2)
	ball.transfer(false, [here, Vector3.ZERO, Vector3.ZERO], 0.1, 25.45)
	PongServo.shared().step_ticks(1)
	assert_lt(
		(PongServo.shared().get_state().ball_position - here).length(),
		(state.ball_position - here).length() - 0.005,
		"a state sent once our touch could have reached the master corrects it"
	)
	# A serve is put at once.
	ball.transfer(true, [here, Vector3.ZERO, Vector3.ZERO], 0.0, 30.0)
	PongServo.shared().step_ticks(1)
	assert_lt((PongServo.shared().get_state().ball_position - here).length(), 0.001, "served")
	# The door checks a correction like a serve.
	expect_error("outside the court")
	assert_false(PongServo.shared().correct_ball(Vector3(0, -1, 0), Vector3.ZERO))


func _open(players: int) -> PongMatch:
	if not assert_true(PongServo.shared().is_available(), "the extension has the Pong renderer"):
		return null
	_pong = PongTestScreen.stepped(PongMatch.Mode.DEMO, players)
	add_child(_pong)
	return _pong.match_node
