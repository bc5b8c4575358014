extends "res://tests/pong/pong_screen_suite.gd"
## Four players on the square court, as plain classes: territories split by the diagonals,
## each seat's frame facing the centre, avatars kept inside their triangle, goals on each
## back wall, players going out and the last one left winning, serves skipping those out,
## the computer aiming at players still in; then a whole 4-computer match in the real
## servo ends with one winner.

const PongTestCourt := preload("res://tests/pong/pong_test_court.gd")
const PongTestScreen := preload("res://tests/pong/pong_test_screen.gd")
const PongTestEvents := preload("res://tests/pong/pong_test_events.gd")
const SURFACE := PongServoFacts.CourtSurface

var _court: PongCourt = null


func before_each() -> void:
	_court = PongTestCourt.make({"players": 4})


func test_the_square_court_and_its_territories() -> void:
	assert_eq(_court.players, 4)
	assert_eq(_court.half_width, _court.half_length, "square")
	assert_eq(_court.territory_at(Vector3(0.2, 1.0, 2.0)), 0)
	assert_eq(_court.territory_at(Vector3(0.2, 1.0, -2.0)), 1)
	assert_eq(_court.territory_at(Vector3(2.0, 1.0, 0.2)), 2)
	assert_eq(_court.territory_at(Vector3(-2.0, 1.0, -0.2)), 3)
	assert_eq(_court.territory_at(Vector3(1.0, 0.0, -1.0)), 1, "a diagonal goes to 0 or 1")
	assert_eq(PongTestCourt.make().territory_at(Vector3(2.0, 1.0, 0.2)), 0, "two players")
	for player: int in 4:
		var toward_centre: Vector3 = -_court.back_wall_centre(player).normalized()
		assert_almost_eq(PongCourt.forward(player), toward_centre, 1e-6, "seat %d" % player)
		var seat: Basis = PongCourt.side_rotation(player)
		assert_almost_eq(seat * Vector3.FORWARD, toward_centre, 1e-6, "device forward")
		assert_almost_eq(seat.determinant(), 1.0, 1e-6, "a rotation")


func test_avatars_stay_inside_their_triangle() -> void:
	var points: Array[Vector3] = [
		Vector3(3.0, 0.0, 3.0), Vector3(-5.0, 0.0, 0.1), Vector3.ZERO, Vector3(0.0, 0.0, -9.0)
	]
	for player: int in 4:
		for point: Vector3 in points:
			var at: Vector3 = _court.clamp_avatar(player, point)
			assert_eq(_court.territory_at(at), player, "player %d from %s" % [player, point])
			var local: Vector3 = PongCourt.side_rotation(player).inverse() * at
			assert_gt(local.z - absf(local.x), PongCourt.AVATAR_MARGIN_M, "off the diagonals")
			assert_lt(local.z, _court.half_length, "inside the back wall")
			assert_almost_eq(at.y, _court.beginner_height, 1e-6)


func test_a_goal_costs_the_back_walls_owner_and_the_last_one_left_wins() -> void:
	var rules: PongRules = PongRules.new(10, 4)
	var outs: Array[int] = []
	var winners: Array[int] = []
	rules.player_out.connect(func(player: int) -> void: outs.append(player))
	rules.match_over.connect(func(winner: int) -> void: winners.append(winner))
	var goal: int = PongRules.DAMAGE[PongRules.CAUSE_GOAL]
	var wall_of_2: PongEvent = PongTestEvents.wall_hit(SURFACE.RIGHT, 2, Vector3(3, 1, 0.3))
	assert_eq(rules.apply_event(wall_of_2, _court, false), 2, "the right wall is 2's goal")
	assert_eq(rules.get_health(2), 10 - goal)
	var ceiling: PongEvent = PongTestEvents.wall_hit(SURFACE.CEILING, -1)
	assert_eq(rules.apply_event(ceiling, _court, false), -1, "the ceiling is nobody's goal")
	assert_eq(outs, [2] as Array[int], "a goal took all 10: player 2 is out")
	assert_false(rules.is_over(), "three are left")
	assert_eq(rules.apply_event(wall_of_2, _court, false), -1, "an out player loses nothing")
	var floor_of_2: PongEvent = PongTestEvents.floor_bounce(2)
	assert_eq(rules.apply_event(floor_of_2, _court, false), -1, "nor on its floor")
	assert_eq(rules.alive(), [0, 1, 3] as Array[int])
	assert_eq(rules.hurt(0, PongRules.CAUSE_GOAL), 10)
	assert_eq(rules.hurt(3, PongRules.CAUSE_GOAL), 10)
	assert_eq(outs, [2, 0, 3] as Array[int])
	assert_true(rules.is_over())
	assert_eq(rules.winner, 1, "the last one left")
	assert_eq(winners, [1] as Array[int], "match_over once")
	assert_eq(rules.hurt(1, PongRules.CAUSE_FLOOR), 0, "frozen once over")
	# Beginner mode: only within the target, measured along the wall (z for players 2, 3).
	var beginner: PongRules = PongRules.new(99, 4)
	var beside: PongEvent = PongTestEvents.wall_hit(SURFACE.RIGHT, 2, Vector3(3.0, 1.0, 0.8))
	assert_eq(beginner.apply_event(beside, _court, true), -1, "beside 2's target")
	assert_eq(beginner.apply_event(wall_of_2, _court, true), 2, "within it")
	# Two players outside beginner mode: back walls are no goals (the paper's rule).
	var two: PongRules = PongRules.new(99)
	var near: PongEvent = PongTestEvents.wall_hit(SURFACE.BACK_NEAR, 0)
	assert_eq(two.apply_event(near, PongTestCourt.make(), false), -1)


func test_serves_go_round_and_the_computer_aims_at_players_still_in() -> void:
	var referee: PongReferee = PongReferee.new()
	referee.players = 4
	var receivers: Array[int] = []
	for i: int in 5:
		receivers.append(referee.receiver)
		var serve: PongReferee.Serve = referee.make_serve(
			_court, _court.clamp_avatar(referee.receiver, Vector3.ZERO), false
		)
		assert_gt(serve.velocity.length(), 0.5)
	assert_eq(receivers, [0, 1, 2, 3, 0] as Array[int])
	var ai: PongAi = PongAi.new(2, _court, 0.5, 7)
	assert_eq(_court.territory_at(ai.home()), 2, "it waits in its own triangle")
	ai.targets.assign([3] as Array[int])
	var from: Vector3 = Vector3(2.0, 0.9, 0.0)
	var v: Vector3 = ai.wanted_velocity(from)
	assert_lt(v.x, -0.5, "toward the -x side, player 3's")
	# Where the lob lands: player 3's territory (no drag, the flight's own formula).
	var g: float = _court.gravity
	var t: float = (v.y + sqrt(v.y * v.y + 2.0 * g * (from.y - _court.ball_radius))) / g
	var land: Vector3 = from + v * t
	assert_eq(_court.territory_at(land), 3, "lands in 3's triangle at %s" % land)


func test_a_four_computer_match_ends_with_one_winner() -> void:
	if not PongServo.shared().is_available():
		skip("no Pong renderer")
		return
	_pong = PongTestScreen.stepped(PongMatch.Mode.DEMO, 4, 6, true)
	add_child(_pong)
	var match_node: PongMatch = _pong.match_node
	assert_eq(match_node.court.players, 4)
	assert_eq(PongServo.shared().get_state().player_count, 4, "the servo has four paddles")
	var outs: Array[int] = []
	match_node.player_out.connect(func(player: int) -> void: outs.append(player))
	var territories: Dictionary[int, bool] = {}
	match_node.event_seen.connect(
		func(event: PongEvent) -> void:
			if event.type == PongServoFacts.PongEventType.TERRITORY:
				territories[event.territory] = true
	)
	var over: bool = match_node.run_until(match_node.rules.is_over, 600.0)
	assert_true(over, "over within 600 simulated s")
	assert_eq(outs.size(), 3, "three went out")
	var winner: int = match_node.rules.winner
	assert_false(outs.has(winner))
	assert_gt(match_node.rules.get_health(winner), 0)
	assert_eq(territories.size(), 4, "the ball visited every triangle")
	await _free_pong()
	assert_eq(PongServo.shared().get_settings().players, 2, "the servo is back to two players")
