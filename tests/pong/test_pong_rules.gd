extends TestSuite
## The match rules as plain classes: health and the winner, beginner goals, the mines'
## placement rule and triggering, the effects' clocks, bullets, and the referee's serves.

const PongTestCourt := preload("res://tests/pong/pong_test_court.gd")
const PongTestEvents := preload("res://tests/pong/pong_test_events.gd")

var _court: PongCourt = null


func before_each() -> void:
	_court = PongTestCourt.make()


func test_a_floor_bounce_costs_one_point_to_its_territorys_owner() -> void:
	var rules: PongRules = PongRules.new(10)
	var hurt: int = rules.apply_event(PongTestEvents.floor_bounce(1), _court, false)
	assert_eq(hurt, 1)
	assert_eq(rules.get_health(1), 9)
	assert_eq(rules.get_health(0), 10, "the other player keeps everything")
	rules.apply_event(PongTestEvents.paddle_touch(0), _court, false)
	var back_near: PongEvent = PongTestEvents.wall_hit(
		PongTestEvents.SURFACE.BACK_NEAR, 0, Vector3(0, 1, 3)
	)
	rules.apply_event(back_near, _court, false)
	assert_eq([rules.get_health(0), rules.get_health(1)], [10, 9], "no other event hurts")


func test_reaching_zero_ends_the_match_and_freezes_health() -> void:
	var rules: PongRules = PongRules.new(3)
	var winners: Array[int] = []
	rules.match_over.connect(func(winner: int) -> void: winners.append(winner))
	assert_eq(rules.hurt(0, PongRules.CAUSE_BULLET), 3, "a bullet costs 3")
	assert_eq(rules.get_health(0), 0)
	assert_true(rules.is_over())
	assert_eq(rules.winner, 1)
	assert_eq(winners, [1] as Array[int], "match_over once")
	assert_eq(rules.hurt(1, PongRules.CAUSE_FLOOR), 0, "nothing changes once over")
	assert_eq(rules.get_health(1), 3)
	rules.reset()
	assert_eq([rules.get_health(0), rules.winner], [3, -1])


func test_damage_never_goes_below_zero() -> void:
	var rules: PongRules = PongRules.new(2)
	assert_eq(rules.hurt(1, PongRules.CAUSE_MINE), 2, "a mine costs at most what is left")
	assert_eq(rules.get_health(1), 0)


func test_a_beginner_goal_needs_the_target_on_the_back_wall() -> void:
	var rules: PongRules = PongRules.new(99)
	var far: PongServoFacts.CourtSurface = PongTestEvents.SURFACE.BACK_FAR
	var inside: PongEvent = PongTestEvents.wall_hit(far, 1, Vector3(0.3, 0.9, -3))
	var outside: PongEvent = PongTestEvents.wall_hit(far, 1, Vector3(0.8, 0.9, -3))
	var left: PongServoFacts.CourtSurface = PongTestEvents.SURFACE.LEFT
	var side: PongEvent = PongTestEvents.wall_hit(left, -1, Vector3(-1.5, 0.9, -1))
	assert_eq(rules.apply_event(outside, _court, true), -1, "beside the target")
	assert_eq(rules.apply_event(side, _court, true), -1, "a side wall")
	assert_eq(rules.apply_event(inside, _court, false), -1, "not in beginner mode")
	assert_eq(rules.apply_event(inside, _court, true), 1, "the far wall's target: player 1")
	assert_eq(rules.get_health(1), 99 - PongRules.DAMAGE[PongRules.CAUSE_GOAL])
	inside.wall = PongTestEvents.SURFACE.BACK_NEAR
	inside.back_wall_of = 0
	assert_eq(rules.apply_event(inside, _court, true), 0)


func test_a_mine_lands_mirrored_across_the_centre_line() -> void:
	var mines: PongMines = PongMines.new()
	assert_almost_eq(
		PongMines.landing_point(0, Vector3(0.5, 0.9, 2.0), _court), Vector3(0.5, 0, -2.0), 1e-6
	)
	assert_almost_eq(
		PongMines.landing_point(1, Vector3(-0.4, 0.9, -1.2), _court), Vector3(-0.4, 0, 1.2), 1e-6
	)
	var near_line: Vector3 = PongMines.landing_point(0, Vector3(9.0, 0.9, 0.1), _court)
	assert_almost_eq(near_line.z, -PongMines.MIN_NET_DISTANCE_M, 1e-6, "kept off the line")
	assert_lt(near_line.x, _court.half_width, "kept inside the side wall")
	assert_eq(mines.left(0), 4)


func test_each_player_places_four_mines_one_of_each_kind() -> void:
	var mines: PongMines = PongMines.new()
	var kinds: Array[String] = []
	for i: int in 4:
		var mine: PongMines.Mine = mines.place(1, Vector3(-1.0 + 0.6 * i, 0.9, -2.0), _court)
		if assert_not_null(mine, "mine %d" % i):
			kinds.append(mine.kind)
			assert_eq(PongCourt.territory_of(mine.position), 0, "in the opponent's half")
	assert_eq(kinds, PongMines.KINDS)
	assert_null(mines.place(1, Vector3(0, 0.9, -1.0), _court), "no fifth mine")
	assert_eq(mines.left(1), 0)
	assert_eq(mines.left(0), 4, "the other player's mines are their own")


func test_a_mine_too_close_to_another_is_kept_in_hand() -> void:
	var mines: PongMines = PongMines.new()
	assert_not_null(mines.place(0, Vector3(0, 0.9, 2), _court))
	assert_null(mines.place(0, Vector3(0.2, 0.9, 2), _court))
	assert_eq(mines.left(0), 3)


func test_only_the_victims_avatar_sets_a_mine_off_once() -> void:
	var mines: PongMines = PongMines.new()
	var mine: PongMines.Mine = mines.place(0, Vector3(0.5, 0.9, 2.0), _court)
	assert_null(mines.step_on(0, Vector3(0.5, 0.9, -2.0)), "its owner cannot set it off")
	var edge: float = PongMines.TRIGGER_RADIUS_M
	assert_null(mines.step_on(1, Vector3(0.5 + edge + 0.05, 0.9, -2.0)), "just beside it")
	assert_eq(mines.step_on(1, Vector3(0.5 + edge - 0.05, 0.9, -2.0)), mine, "on it")
	assert_eq(mines.placed.size(), 0, "gone")
	assert_null(mines.step_on(1, Vector3(0.5, 0.9, -2.0)))


func test_an_effect_runs_for_its_duration_and_ramps() -> void:
	var effects: PongEffects = PongEffects.new()
	effects.ramp_s = 0.25
	effects.start(1, "slow", 4.0, 0)
	assert_eq(effects.kind_of(1), "slow")
	assert_eq(effects.strength(1), 0.0, "ramps in from nothing")
	effects.advance(0.125)
	assert_almost_eq(effects.strength(1), 0.5, 1e-4)
	effects.advance(1.0)
	assert_almost_eq(effects.speed_factor(1), PongEffects.SLOW_SPEED_FACTOR, 1e-4)
	assert_almost_eq(effects.remaining(1), 4.0 - 1.125, 1e-4)
	var state: PongEffectState = effects.state_of(1)
	if assert_not_null(state, "the effect as the servo reports the device player's"):
		assert_eq(state.kind, PongServoFacts.PongEffectKind.SLOW)
		assert_almost_eq(state.remaining_s, 4.0 - 1.125, 1e-4)
	effects.advance(2.8)
	assert_eq(effects.kind_of(1), "slow", "still on just before the end")
	effects.advance(0.1)
	assert_eq(effects.kind_of(1), "", "over after 4 s")
	assert_eq(effects.speed_factor(1), 1.0)
	assert_eq(effects.kind_of(0), "", "the other player never had it")
	assert_null(effects.state_of(1), "no state once over")


func test_heavy_sags_and_remote_pulls_toward_the_owners_mirror_image() -> void:
	var effects: PongEffects = PongEffects.new()
	effects.ramp_s = 0.0
	effects.start(0, "heavy", 4.0, 1)
	assert_almost_eq(
		effects.affect_offset(0, Vector3.ZERO, Vector3.ZERO),
		Vector3.DOWN * PongEffects.HEAVY_SAG_M,
		1e-6
	)
	effects.start(0, "remote", 4.0, 1)
	# The owner (player 1, facing +z) holds its paddle to its own right: world -x.
	var owner_offset: Vector3 = Vector3(-0.3, 0.1, 0.0)
	var pulled: Vector3 = effects.affect_offset(0, Vector3.ZERO, owner_offset)
	# Its right is our right mirrored: our left, world -x.
	assert_almost_eq(pulled, Vector3(-0.3, 0.1, 0.0) * PongEffects.REMOTE_PULL, 1e-6)


func test_no_effect_moves_a_paddle_beyond_its_reach() -> void:
	var effects: PongEffects = PongEffects.new()
	effects.ramp_s = 0.0
	effects.reach = 0.5
	effects.start(0, "remote", 4.0, 1)
	var pulled: Vector3 = effects.affect_offset(0, Vector3.ZERO, Vector3.DOWN * 4.65)
	assert_almost_eq(pulled, Vector3.DOWN * 0.5 * PongEffects.REMOTE_PULL, 1e-6, "target held")
	pulled = effects.affect_offset(0, Vector3.DOWN * 3.0, Vector3.DOWN * 4.65)
	assert_almost_eq(pulled.length(), 0.5, 1e-6, "the paddle held too")
	effects.start(0, "heavy", 4.0, 1)
	var sagged: Vector3 = effects.affect_offset(0, Vector3(0.0, -0.45, 0.0), Vector3.ZERO)
	assert_almost_eq(sagged, Vector3.DOWN * 0.5, 1e-6)


func test_bullets_hit_the_other_avatar_and_respect_the_cooldown() -> void:
	var bullets: PongBullets = PongBullets.new()
	var avatars: Array[Vector3] = [Vector3(0, 0.9, 2), Vector3(0.1, 0.9, -2)]
	assert_not_null(bullets.fire(0, Vector3(0, 0.6, 1.6), Vector3.FORWARD))
	assert_null(bullets.fire(0, Vector3(0, 0.6, 1.6), Vector3.FORWARD), "cooling down")
	var hits: Array[Dictionary] = []
	for i: int in 100:
		hits.append_array(bullets.advance(0.01, _court, avatars))
	assert_eq(hits.size(), 1, "one hit")
	if hits.size() == 1:
		assert_eq(hits[0]["victim"], 1)
		assert_eq(hits[0]["owner"], 0)
		assert_almost_eq(hits[0]["direction"], Vector3.FORWARD, 1e-6)
	assert_eq(bullets.flying.size(), 0, "the bullet is spent")
	assert_true(bullets.can_fire(0), "cooled down")


func test_a_bullet_that_misses_leaves_the_court() -> void:
	var bullets: PongBullets = PongBullets.new()
	var avatars: Array[Vector3] = [Vector3(0, 0.9, 2), Vector3(1.0, 0.9, -2)]
	bullets.fire(0, Vector3(-0.5, 0.6, 1.6), Vector3.FORWARD)
	var hits: Array[Dictionary] = []
	for i: int in 200:
		hits.append_array(bullets.advance(0.01, _court, avatars))
	assert_eq(hits.size(), 0)
	assert_eq(bullets.flying.size(), 0, "gone through the back wall")


func test_the_referee_serves_first_then_after_a_stall() -> void:
	var referee: PongReferee = PongReferee.new()
	assert_false(referee.update(PongReferee.FIRST_SERVE_DELAY_S * 0.5, Vector3.ZERO))
	assert_true(referee.update(PongReferee.FIRST_SERVE_DELAY_S, Vector3.ZERO), "first serve")
	referee.make_serve(_court, Vector3(0, 0.9, 2), false)
	var waited: float = 0.0
	while not referee.update(0.1, Vector3(0.1, 0, 0)):
		waited += 0.1
		if waited > 10.0:
			break
	assert_almost_eq(waited, PongReferee.STALL_SECONDS, 0.11, "served again after a stall")
	referee.make_serve(_court, Vector3(0, 0.9, -2), false)
	for i: int in 100:
		assert_false(referee.update(0.1, Vector3(2, 0, 0)), "a moving ball is no stall")


func test_a_serve_reaches_the_receivers_workspace_centre() -> void:
	var referee: PongReferee = PongReferee.new()
	var target: Vector3 = Vector3(0.4, 0.9, 2.0)
	var serve: PongReferee.Serve = referee.make_serve(_court, target, false)
	assert_eq(referee.receiver, 1, "the next serve goes to the other player")
	var t: float = PongReferee.SERVE_FLIGHT_S
	var arrive: Vector3 = PongPredictor.parabola_at(serve.position, serve.velocity, 6.0, t)
	assert_almost_eq(arrive, target, 1e-4)
	var flat: PongReferee.Serve = referee.make_serve(_court, Vector3(0, 0.9, -2), true)
	assert_almost_eq(flat.position.y, _court.beginner_height, 1e-6, "beginner: in the plane")
	assert_eq(flat.velocity.y, 0.0)
	assert_lt(flat.velocity.z, 0.0, "toward player 1")
