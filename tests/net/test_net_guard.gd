extends "res://tests/net/net_play_suite.gd"
## The guards of networked Pong, without sockets (the heartbeat: test_net_heartbeat.gd): the
## budget of bad messages, the cap on unauthenticated connections per address, and the
## server's judgement of floor hurts against the ball's recorded path (on its own, then on
## the host of a real stepped match, where a client was the master).

const PongTestCourt := preload("res://tests/pong/pong_test_court.gd")
## A point of each territory of the test court (territory 0: z >= 0).
const NEAR: Vector3 = Vector3(0.3, 0.07, 1.5)
const FAR: Vector3 = Vector3(0.3, 0.07, -1.5)
## Past the longest a claim waits for its bounce, seconds after it arrived.
const LATE_S: float = PongNetHurtJudge.STREAM_WAIT_S + 0.1

# --- bad messages ---


func test_the_budget_warns_once_then_counts_then_disconnects_once() -> void:
	var budget: PongNetBudget = PongNetBudget.new(4)
	var verdicts: Array = []
	for i: int in 6:
		verdicts.append(budget.note(5))
	assert_eq(
		verdicts,
		[
			PongNetBudget.Verdict.WARN,
			PongNetBudget.Verdict.COUNT,
			PongNetBudget.Verdict.COUNT,
			PongNetBudget.Verdict.DISCONNECT,
			PongNetBudget.Verdict.COUNT,
			PongNetBudget.Verdict.COUNT
		]
	)
	assert_eq(budget.note(6), PongNetBudget.Verdict.WARN, "each peer has its own count")
	assert_eq(budget.count_of(5), 6)
	var warn: String = budget.log_line(
		PongNetBudget.Verdict.WARN, 5, "pose", "seat 7 is out of [0, 1]"
	)
	assert_true(warn.contains("peer 5 sent a bad pose (seat 7") and warn.contains("4"), warn)
	assert_eq(
		budget.log_line(PongNetBudget.Verdict.COUNT, 5, "pose", "x"), "", "counted, not logged"
	)
	var huge: String = budget.log_line(
		PongNetBudget.Verdict.DISCONNECT, 5, "hurt", "x".repeat(65536)
	)
	assert_true(huge.begins_with("PongNet: disconnecting peer 5: 4 bad"), huge.left(80))
	assert_lt(huge.length(), PongNetBudget.REASON_LOG_CHARS + 100, "a huge reason is cut")
	budget.forget(5)
	assert_eq(budget.note(5), PongNetBudget.Verdict.WARN, "a new peer with an old id starts afresh")
	assert_eq(PongNetBudget.new().limit, PongNetProtocol.MISBEHAVIOUR_BUDGET)


func test_a_rare_bad_message_is_forgiven_and_a_burst_is_not() -> void:
	var budget: PongNetBudget = PongNetBudget.new()
	var now: Array[float] = [0.0]
	budget.clock = func() -> float: return now[0]
	# An honest peer refused now and then over a long session: never given up on.
	for i: int in 3 * PongNetProtocol.MISBEHAVIOUR_BUDGET:
		assert_ne(budget.note(5), PongNetBudget.Verdict.DISCONNECT, "refusal %d" % i)
		now[0] += PongNetProtocol.MISBEHAVIOUR_FORGIVEN_S * 1.5
	assert_eq(budget.count_of(5), 3 * PongNetProtocol.MISBEHAVIOUR_BUDGET, "all counted")
	# A forger's burst, in a second: given up on at the limit.
	var verdicts: Array = []
	for i: int in PongNetProtocol.MISBEHAVIOUR_BUDGET:
		verdicts.append(budget.note(6))
		now[0] += 1.0 / PongNetProtocol.MISBEHAVIOUR_BUDGET
	assert_eq(verdicts.count(PongNetBudget.Verdict.DISCONNECT), 1)
	assert_eq(verdicts[-1], PongNetBudget.Verdict.DISCONNECT)


func test_one_address_holds_a_few_unauthenticated_connections_the_oldest_go() -> void:
	var open: PongNetHalfOpen = PongNetHalfOpen.new(2)
	assert_eq(open.add(10, "10.0.0.1", 1.0), [])
	assert_eq(open.add(11, "10.0.0.1", 1.0), [])
	assert_eq(open.add(20, "10.0.0.2", 1.0), [], "another address has its own")
	assert_eq(open.add(12, "10.0.0.1", 1.0), [10], "a third from one address: the oldest goes")
	assert_eq(open.add(13, "10.0.0.1", 2.0), [11])
	assert_eq([open.count("10.0.0.1"), open.count("10.0.0.2")], [2, 1])
	open.remove(12)
	assert_eq(open.add(14, "10.0.0.1", 3.0), [], "one passed the check: room again")
	assert_eq(PongNetHalfOpen.new().per_address, PongNetProtocol.HALF_OPEN_PER_ADDRESS)


# --- floor hurts against the recorded path ---


func _judge() -> PongNetHurtJudge:
	return PongNetHurtJudge.new(PongTestCourt.make(), 2)


# A ball falling onto [param at] at [param t] and rising again, sampled every 5 ms.
func _bounce_path(judge: PongNetHurtJudge, at: Vector3, t: float) -> void:
	for i: int in range(-10, 10):
		var dt: float = i * 0.005
		var vy: float = -3.0 if i < 0 else 2.5
		var height: float = absf(vy * dt) + 0.07
		judge.observe(t + dt, Vector3(at.x, height, at.z), Vector3(0.5, vy, -1.0))


func test_a_claim_is_accepted_for_one_bounce_in_the_victims_territory_once() -> void:
	var judge: PongNetHurtJudge = _judge()
	var accept: int = PongNetHurtJudge.Verdict.ACCEPT
	var wait: int = PongNetHurtJudge.Verdict.WAIT
	var refuse: int = PongNetHurtJudge.Verdict.REFUSE
	_bounce_path(judge, FAR, 10.0)
	assert_eq(judge.bounces().size(), 1, "the turn near the floor is one bounce")
	assert_eq(judge.judge(10.1, 10.1, 1, 1)[0], accept, "the far seat's bounce, claimed")
	assert_eq(judge.judge(10.2, 10.2, 1, 1)[0], wait, "a second claim waits for another bounce")
	var again: Array = judge.judge(10.2 + LATE_S, 10.2, 1, 1)
	assert_eq(again[0], refuse)
	assert_true(str(again[1]).contains("charged already"), str(again[1]))
	var forged: Array = judge.judge(10.2 + LATE_S, 10.2, 0, 1)
	assert_eq(forged[0], refuse, "no bounce in the near territory: the near seat loses nothing")
	assert_true(str(forged[1]).contains("no floor bounce in territory 0"), str(forged[1]))


func test_a_forged_flood_is_refused_and_real_bounces_are_not_lost() -> void:
	var judge: PongNetHurtJudge = _judge()
	var forged: int = 0
	var real: int = 0
	# The issue's attack: 120 claims that the near seat lost points while the ball bounced
	# in the far territory (the cheat's own), over 12 s with a bounce there every second;
	# the cheat's real bounces are claimed too.
	for second: int in 12:
		var t: float = 20.0 + second
		_bounce_path(judge, FAR, t)
		for claim: int in 10:
			var at: float = t + 0.1 + claim * 0.05
			var verdict: Array = judge.judge(at + PongNetHurtJudge.WAIT_S, at, 0, 1)
			forged += 1 if verdict[0] == PongNetHurtJudge.Verdict.ACCEPT else 0
		var own: Array = judge.judge(t + 0.2, t + 0.1, 1, 1)
		real += 1 if own[0] == PongNetHurtJudge.Verdict.ACCEPT else 0
	assert_eq(forged, 0, "none of 120 forged hurts")
	assert_eq(real, 12, "every real bounce, once")
	assert_eq(judge.judge(31.5 + LATE_S, 31.5, 1, 1)[0], PongNetHurtJudge.Verdict.REFUSE, "no 13th")


func test_a_claim_may_come_before_our_copy_of_the_ball_bounces() -> void:
	var judge: PongNetHurtJudge = _judge()
	assert_eq(judge.judge(5.0, 5.0, 0, 0)[0], PongNetHurtJudge.Verdict.WAIT)
	judge.observe_floor(5.3, NEAR)
	assert_eq(judge.judge(5.3, 5.0, 0, 0)[0], PongNetHurtJudge.Verdict.ACCEPT)
	var late: Array = judge.judge(5.5, 5.01, 0, 0)
	assert_eq(late[0], PongNetHurtJudge.Verdict.WAIT, "no second bounce yet, still waiting")


func test_a_claim_waits_for_the_masters_stream_to_catch_up_with_it() -> void:
	var judge: PongNetHurtJudge = _judge()
	var wait: int = PongNetHurtJudge.Verdict.WAIT
	# After a hiccup the reliable claim came first: the newest state played is older.
	judge.observe_master(4.80, Vector3(0.3, 0.5, -1.3), Vector3(0.0, -3.0, -1.0))
	assert_eq(judge.judge(5.0 + PongNetHurtJudge.WAIT_S + 0.5, 5.0, 1, 1)[0], wait)
	# The states either side of its bounce, and one after the claim, come.
	judge.observe_master(4.95, Vector3(0.3, 0.1, -1.4), Vector3(0.0, 2.5, -1.0))
	judge.observe_master(5.10, Vector3(0.3, 0.4, -1.5), Vector3(0.0, 1.0, -1.0))
	assert_eq(judge.judge(6.6, 5.0, 1, 1)[0], PongNetHurtJudge.Verdict.ACCEPT, "its bounce")
	# Caught up, and no bounce: refused after the least wait.
	judge.observe_master(10.2, Vector3(0.3, 1.2, -1.5), Vector3(0.0, -1.0, -1.0))
	var caught_up: Array = judge.judge(10.0 + PongNetHurtJudge.WAIT_S, 10.0, 1, 1)
	assert_eq(caught_up[0], PongNetHurtJudge.Verdict.REFUSE, "no bounce in states past it")
	# A stream that never comes back: refused after the longest.
	assert_eq(judge.judge(20.0 + LATE_S - 0.2, 20.0, 1, 1)[0], wait)
	assert_eq(judge.judge(20.0 + LATE_S, 20.0, 1, 1)[0], PongNetHurtJudge.Verdict.REFUSE)


func test_a_turn_high_in_the_air_is_no_bounce() -> void:
	var judge: PongNetHurtJudge = _judge()
	# A paddle lifts a falling ball 1.1 m above the floor.
	judge.observe(1.0, Vector3(0.0, 1.1, 1.0), Vector3(0.0, -3.0, 1.0))
	judge.observe(1.005, Vector3(0.0, 1.1, 1.0), Vector3(0.0, 4.0, -3.0))
	assert_eq(judge.bounces(), [], "not near the floor")
	# A follower's copy turns up a little above the floor when the master's state arrives.
	judge.observe(2.0, Vector3(0.0, 0.2, 1.0), Vector3(0.0, -3.0, 1.0))
	judge.observe(2.008, Vector3(0.0, 0.18, 1.0), Vector3(0.0, 2.5, 1.0))
	assert_eq(judge.bounces().size(), 1)


func test_the_masters_own_states_show_a_bounce_our_blended_copy_flew_over() -> void:
	var judge: PongNetHurtJudge = _judge()
	# CI's refused honest claim: our copy fell 1.48 -> 0.63 m onto the state played after
	# the master's bounce, and turned up there, far above the floor.
	judge.observe(1.00, Vector3(0.3, 1.48, -1.3), Vector3(0.0, -15.0, -1.0))
	judge.observe(1.01, Vector3(0.3, 0.63, -1.4), Vector3(0.0, 0.3, -1.0))
	assert_eq(judge.bounces(), [], "no turn near the floor in our copy")
	# The master's states, 10 ms apart, either side of its bounce.
	judge.observe_master(0.95, Vector3(0.3, 0.11, -1.3), Vector3(0.0, -3.6, -1.0))
	judge.observe_master(0.96, Vector3(0.3, 0.098, -1.35), Vector3(0.0, 2.9, -1.0))
	assert_eq(judge.bounces().size(), 1, "a turn the ball could fall and rise in")
	assert_eq(judge.judge(1.1, 1.05, 1, 1)[0], PongNetHurtJudge.Verdict.ACCEPT)
	# A paddle lifting a falling ball 0.5 m up, between states 10 ms apart: no bounce.
	judge.observe_master(2.00, Vector3(0.3, 0.5, -1.3), Vector3(0.0, -3.0, -1.0))
	judge.observe_master(2.01, Vector3(0.3, 0.5, -1.3), Vector3(0.0, 4.0, 1.0))
	assert_eq(judge.bounces().size(), 1, "too high to have touched the floor")
	# Two states 0.3 s apart (the ones between lost) may hold a bounce lower than the fall.
	judge.observe_master(3.0, Vector3(0.3, 0.6, -1.3), Vector3(0.0, -1.5, -1.0))
	judge.observe_master(3.3, Vector3(0.3, 0.4, -1.6), Vector3(0.0, 1.2, -1.0))
	assert_eq(judge.bounces().size(), 2, "0.6 m is within 0.3 s of fall at 1.5 m/s")


func test_a_bounce_counts_only_within_the_claimants_epoch() -> void:
	var judge: PongNetHurtJudge = _judge()
	judge.observe_floor(4.0, NEAR)
	# The near seat's ball bounced at 4.0 s. A master from 1.0 to 3.0 s, or from 5.0 s on,
	# cannot have seen it.
	var ended: Array = judge.judge(4.2 + LATE_S, 4.2, 0, 0, 1.0, 3.0)
	assert_eq(ended[0], PongNetHurtJudge.Verdict.REFUSE, "after the claimant's epoch ended")
	var later: Array = judge.judge(5.2 + LATE_S, 5.2, 0, 0, 5.0)
	assert_eq(later[0], PongNetHurtJudge.Verdict.REFUSE, "before the claimant's epoch began")
	var slack: Array = judge.judge(4.3, 4.2, 0, 0, 1.0, 3.8)
	assert_eq(slack[0], PongNetHurtJudge.Verdict.ACCEPT, "a leg's slack at the epoch's end")


func test_the_master_trusts_its_servos_floor_events_not_turns_of_the_ball() -> void:
	var judge: PongNetHurtJudge = _judge()
	# Our own paddle lifts the ball just above the floor while we are the master.
	judge.observe(1.0, Vector3(0.0, 0.15, 1.0), Vector3(0.0, -3.0, 1.0), true)
	judge.observe(1.005, Vector3(0.0, 0.16, 1.0), Vector3(0.0, 4.0, -3.0), true)
	assert_eq(judge.bounces(), [], "no floor event: no bounce")
	judge.observe_floor(2.0, NEAR, true)
	assert_eq(judge.bounces().size(), 1, "the servo's bounce, charged already")
	assert_eq(judge.judge(2.1 + LATE_S, 2.1, 0, 0)[0], PongNetHurtJudge.Verdict.REFUSE)


func test_the_margin_is_only_for_the_territory_the_ball_was_in() -> void:
	var judge: PongNetHurtJudge = _judge()
	# Our copy bounced 0.4 m past the line into the near half; the master's, in the far.
	judge.observe_floor(3.0, Vector3(0.0, 0.07, 0.4))
	var strict: Array = judge.judge(3.1 + LATE_S, 3.1, 1, 0)
	assert_eq(strict[0], PongNetHurtJudge.Verdict.REFUSE, "the far seat, claimed at epoch near")
	assert_eq(judge.judge(3.1, 3.1, 1, 1)[0], PongNetHurtJudge.Verdict.ACCEPT, "at epoch far")
	judge.observe_floor(6.0, Vector3(0.0, 0.07, 0.4))
	assert_eq(judge.judge(6.1, 6.1, 0, 1)[0], PongNetHurtJudge.Verdict.ACCEPT, "strictly inside")


# --- on the host of a stepped match ---


func _client_master_at_epoch_one(play: PongNetPlay) -> void:
	var transfer: Dictionary = play.authority.next_transfer(PongNetFacts.TransferKind.SERVE, 1)
	assert_eq(play.authority.apply_transfer(HOST, transfer), "")
	assert_eq(play.authority.master_at(1), CLIENT)


# The judge's clock, moved by hand: [0] is now.
func _hand_clock(hurts: PongNetFloorHurts) -> Array[float]:
	var clock: Array[float] = [100.0]
	hurts.clock = func() -> float: return clock[0]
	return clock


func _claim(epoch: int, victim: int) -> PongNetFloorClaimMessage:
	var claim: PongNetFloorClaimMessage = PongNetFloorClaimMessage.new()
	claim.epoch = epoch
	claim.victim = victim
	return claim


func _floor_hurt(epoch: int, victim: int) -> PongNetFloorHurtMessage:
	var hurt: PongNetFloorHurtMessage = PongNetFloorHurtMessage.new()
	hurt.epoch = epoch
	hurt.victim = victim
	return hurt


func test_the_host_charges_a_clients_claim_for_a_bounce_it_saw_and_no_forgery() -> void:
	var play: PongNetPlay = _open_play()
	if play == null:
		return
	_client_master_at_epoch_one(play)
	var rules: PongRules = play.match_node.rules
	var start: int = rules.get_health(0)
	var hurts: PongNetFloorHurts = play.floor_hurts
	var clock: Array[float] = _hand_clock(hurts)
	for i: int in 40:
		_receive(CLIENT, _claim(1, 0))
	var waiting: int = hurts.judge.max_waiting()
	assert_eq(_refused("floor claim"), 40 - waiting, "no more wait than a ball bounces in it")
	for i: int in 3:
		hurts.on_claim(HOST, _claim(1, 1))
	clock[0] += LATE_S
	hurts.observe(play.match_node.snapshot)
	assert_eq(rules.get_health(0), start, "40 forged claims on the host's seat: nothing")
	assert_eq(_refused("floor claim"), 43, "each refused and counted")
	assert_eq(play.session.budget.count_of(CLIENT), 40)
	assert_eq(_router.sent_of(PongNetFloorHurtMessage.SCHEMA_ID), [], "nothing charged")
	hurts.judge.observe_floor(hurts.now(), FAR)
	_receive(CLIENT, _claim(1, 1))
	assert_eq(rules.get_health(1), start - 1, "the client's own bounce costs it a point")
	var charged: Array[PongNetMessage] = _router.sent_of(PongNetFloorHurtMessage.SCHEMA_ID)
	assert_eq(charged.size(), 1, "charged on every peer")
	if charged.size() == 1:
		var hurt: PongNetFloorHurtMessage = charged[0]
		assert_eq([hurt.epoch, hurt.victim], [1, 1])
	assert_eq(_report.hurts, [[1, 1, "floor"]])


func test_a_stall_of_the_host_does_not_slide_a_bounce_out_of_its_epoch() -> void:
	# A windowed host's match time counts a 1.5 s stall as 0.1 s; the master's states that
	# waited meanwhile are aged by this machine's clock. The client's honest claim of a
	# bounce 0.2 s into its epoch was refused when the bounce was placed on match time.
	var play: PongNetPlay = _open_play()
	if play == null:
		return
	var rules: PongRules = play.match_node.rules
	var start: int = rules.get_health(1)
	var hurts: PongNetFloorHurts = play.floor_hurts
	var clock: Array[float] = _hand_clock(hurts)
	_client_master_at_epoch_one(play)
	hurts.observe(play.match_node.snapshot)
	clock[0] += 1.5
	play.match_node.now += 0.1
	# Played now, 1.3 s old: the master's ball either side of its bounce at 100.2 s.
	var ball: Array[Array] = [
		[Vector3(0.3, 0.11, -1.3), Vector3(0.0, -3.6, -1.0)],
		[Vector3(0.3, 0.098, -1.35), Vector3(0.0, 2.9, -1.0)],
	]
	var states: Array[PongNetBallBuffer.State] = []
	for i: int in ball.size():
		var at: Array[Vector3] = [ball[i][0], ball[i][1], Vector3.ZERO]
		states.append(PongNetBallBuffer.State.new(i + 1, 0.0, at, 50.0, 1.305 - 0.01 * i))
	hurts.observe_master(states, 50.0)
	_receive(CLIENT, _claim(1, 1))
	assert_eq(rules.get_health(1), start - 1, "its bounce, in its epoch: charged")
	assert_eq(_refused("floor claim"), 0)


func test_only_the_server_charges_floor_hurts() -> void:
	var play: PongNetPlay = _open_play()
	if play == null:
		return
	var rules: PongRules = play.match_node.rules
	var start: int = rules.get_health(0)
	_receive(CLIENT, _floor_hurt(0, 0))
	assert_eq(rules.get_health(0), start, "a client's word is not a charge")
	_receive(HOST, _floor_hurt(0, 0))
	assert_eq(rules.get_health(0), start - 1, "the server's is")
	var long: PackedByteArray = _floor_hurt(0, 0).encode() + "x".repeat(65536).to_utf8_buffer()
	_router.receive(HOST, long)
	_receive(HOST, _floor_hurt(0, 5))
	_receive(HOST, _floor_hurt(7, 0))
	assert_eq(rules.get_health(0), start - 1)
	assert_eq(_refused("hurt"), 4, "from a client, too long, seat 5, a future epoch")


func test_a_weapon_hurt_needs_a_weapon_that_could_reach_the_victim() -> void:
	var play: PongNetPlay = _open_play()
	if play == null:
		return
	var weapons: PongNetWeapons = play.weapons
	var rules: PongRules = play.match_node.rules
	var bullet: PongNetFacts.WeaponCause = PongNetFacts.WeaponCause.BULLET
	# The client's shots from its half: one toward its own back wall, one toward the host.
	var origin: Vector3 = Vector3(0.0, 0.8, -2.0)
	_receive(CLIENT, _bullet(1, 0, origin, Vector3.FORWARD, 10.0))
	_receive(CLIENT, _bullet(1, 1, origin, Vector3.BACK, 10.5))
	assert_eq(weapons.shots, [[1, 0], [1, 1]], "both flew")
	weapons.on_hurt(HOST, _weapon_hurt(0, bullet, 1, 0))
	assert_eq(rules.get_health(0), 99, "a shot away from the host's half cannot hit it")
	assert_eq(_refused("weapon hurt"), 1)
	weapons.on_hurt(HOST, _weapon_hurt(0, bullet, 1, 1))
	assert_eq(rules.get_health(0), 99 - PongRules.DAMAGE[PongRules.CAUSE_BULLET], "this one can")


func test_a_mine_reaches_only_the_territory_it_lies_in_or_next_to() -> void:
	var reach: float = PongMines.TRIGGER_RADIUS_M
	var near: Callable = PongNetProtocol.near_territory
	# The square court: territory 0 is z >= |x|, 2 is x > |z|.
	assert_true(near.call(Vector3(0.0, 0.0, 2.0), 0, 4, reach))
	assert_false(near.call(Vector3(0.0, 0.0, 2.0), 2, 4, reach), "deep in 0: not 2's")
	assert_true(near.call(Vector3(1.0, 0.0, 1.2), 2, 4, reach), "0.14 m from the diagonal")
	assert_false(near.call(Vector3(0.0, 0.0, -2.0), 0, 4, reach), "across the court")
