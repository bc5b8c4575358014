extends "res://tests/pong/pong_screen_suite.gd"
## Haptic Battle Pong through the real scene and the real servo (the extension's Pong
## renderer), stepped by the match so that time is simulated time: the computer returns
## served balls, a bounce in one's own half costs exactly one point, a mine's effect starts
## and ends on time in the servo, beginner mode keeps the ball in its plane, and a whole
## computer-vs-computer match ends with a winner. Bounds are generous; every wait has a
## timeout.

const PongTestScreen := preload("res://tests/pong/pong_test_screen.gd")
const PongTestEvents := preload("res://tests/pong/pong_test_events.gd")
const EVENT := PongServoFacts.PongEventType
## Tolerance of an effect's end: one match update either side, and one more for the order
## of update and servo ticks.
const EFFECT_TOLERANCE_S: float = 2.0 * PongMatch.STEP_CHUNK_S + 0.005

var _events: Array[PongEvent] = []


func after_each() -> void:
	get_tree().paused = false
	_events.clear()
	await _free_pong()


func test_the_computer_returns_served_balls() -> void:
	var match_node: PongMatch = _open(PongMatch.Mode.VS_COMPUTER)
	if match_node == null:
		return
	_stand_aside(match_node)
	var court: PongCourt = match_node.court
	var returned: int = 0
	var serves: int = 5
	for i: int in serves:
		var from: Vector3 = Vector3(-0.4 + 0.2 * i, 1.2, 0.6)
		var target: Vector3 = Vector3(
			0.5 - 0.25 * i, court.beginner_height, -court.half_length * (0.45 + 0.05 * i)
		)
		_events.clear()
		PongServo.shared().set_ball(
			from, PongReferee.launch_velocity(from, target, court.gravity, 1.0)
		)
		var hit: bool = match_node.run_until(_saw.bind(EVENT.PADDLE, 1), 3.0)
		var back: bool = hit and match_node.run_until(_ball_in.bind(0), 3.0)
		if hit and back:
			returned += 1
		else:
			print("    serve %d: contact %s, back %s" % [i, hit, back])
	assert_eq(returned, serves, "every serve comes back across the centre line")


func test_a_bounce_in_ones_own_half_costs_exactly_one_point() -> void:
	var match_node: PongMatch = _open(PongMatch.Mode.VS_COMPUTER)
	if match_node == null:
		return
	_stand_aside(match_node)
	var start: int = match_node.rules.start_health
	PongServo.shared().set_ball(Vector3(-0.9, 1.5, 1.5), Vector3(0.0, 0.0, 0.3))
	match_node.run_until(func() -> bool: return false, 4.0)
	var own: int = PongTestEvents.count(_events, EVENT.FLOOR, 0)
	assert_gt(own, 2, "the ball bounced several times in territory 0")
	assert_eq(PongTestEvents.count(_events, EVENT.FLOOR, 1), 0, "never in territory 1")
	assert_eq(match_node.rules.get_health(0), start - own, "one point per bounce")
	assert_eq(match_node.rules.get_health(1), start, "the other player lost nothing")


func test_a_mines_effect_starts_and_ends_on_time() -> void:
	var match_node: PongMatch = _open(PongMatch.Mode.VS_COMPUTER)
	if match_node == null:
		return
	if not assert_eq(match_node.local_player, 0, "player 0 plays on the simulated device"):
		return
	var duration: float = match_node.court.settings.mine_effect_duration_s
	var avatar: Vector3 = match_node.avatar_of(0)
	var mine: PongMines.Mine = match_node.mines.place(
		1, Vector3(avatar.x, 0.0, -avatar.z), match_node.court
	)
	if not assert_not_null(mine, "player 1's mine under player 0"):
		return
	assert_null(_servo_effect(mine.kind), "no effect before")
	var started: bool = match_node.run_until(
		func() -> bool: return _servo_effect(mine.kind) != null, 0.5
	)
	if not assert_true(started, "the servo shows the %s effect" % mine.kind):
		return
	var start_time: float = match_node.now
	var remaining: float = _servo_effect(mine.kind).remaining_s
	assert_almost_eq(remaining, duration, EFFECT_TOLERANCE_S, "it starts with its duration")
	assert_eq(match_node.rules.get_health(0), match_node.rules.start_health - 5, "a mine costs 5")
	await wait_process_frames(2)
	assert_has(_pong.hud.get_panel(0).get_effect_text(), "SLOW", "the HUD shows it")
	var ended: bool = match_node.run_until(
		func() -> bool: return _servo_effect(mine.kind) == null, duration + 1.0
	)
	assert_true(ended, "the effect ends")
	assert_almost_eq(match_node.now - start_time, duration, EFFECT_TOLERANCE_S, "on time")
	assert_null(match_node.effect_of(0), "the game's clock agrees")


func test_beginner_mode_keeps_the_ball_in_its_plane() -> void:
	var match_node: PongMatch = _open(PongMatch.Mode.DEMO, true)
	if match_node == null:
		return
	match_node.auto_serve = true
	var height: float = match_node.court.beginner_height
	var worst: Array[float] = [0.0]
	var check: Callable = func() -> bool:
		if match_node.referee.serves > 0:
			worst[0] = maxf(worst[0], absf(match_node.snapshot.ball_position.y - height))
		return false
	match_node.run_until(check, 12.0)
	assert_gt(match_node.referee.serves, 0, "served")
	assert_gt(PongTestEvents.count(_events, EVENT.PADDLE), 2, "a rally: several paddle contacts")
	assert_lt(worst[0], 0.001, "y stays within 1 mm of the beginner plane")


func test_a_computer_match_runs_to_a_winner() -> void:
	set_timeout(150.0)
	var match_node: PongMatch = _open(PongMatch.Mode.DEMO, false, 5, true)
	if match_node == null:
		return
	match_node.auto_serve = true
	var over: bool = await wait_until(match_node.rules.is_over, 120.0)
	if not assert_true(over, "a winner within the time bound"):
		return
	var winner: int = match_node.rules.winner
	assert_eq(match_node.rules.get_health(1 - winner), 0)
	assert_gt(match_node.rules.get_health(winner), 0)
	print(
		(
			"    match: %.1f simulated s at %.1fx real time, %d serves, %d paddle contacts"
			% [
				match_node.now,
				match_node.speed_ratio(),
				match_node.referee.serves,
				PongTestEvents.count(_events, EVENT.PADDLE)
			]
		)
	)
	await wait_process_frames(2)
	assert_true(_pong.winner_screen.visible, "the winner screen shows")
	var loser: PongPlayerPanel = _pong.hud.get_panel(1 - winner)
	assert_eq(loser.get_health_text(), "0", "the HUD under it shows the loser's last point lost")


# The Pong screen in [param mode], stepped; the match is driven by the test unless
# [param self_stepping]. Null (and a failure) without the Pong renderer.
func _open(
	mode: PongMatch.Mode, beginner: bool = false, health: int = 99, self_stepping: bool = false
) -> PongMatch:
	if not assert_true(PongServo.shared().is_available(), "the extension has the Pong renderer"):
		return null
	_pong = PongTestScreen.stepped(mode, 2, health)
	_pong.beginner = beginner
	var match_node: PongMatch = _pong.get_node(^"Match") as PongMatch
	match_node.self_stepping = self_stepping
	add_child(_pong)
	match_node.event_seen.connect(_events.append)
	for controller: PongController in match_node.controllers:
		if controller is PongAi:
			(controller as PongAi).use_weapons = self_stepping
		elif controller is PongHumanPlayer:
			(controller as PongHumanPlayer).reads_input = false
	return match_node


# Player 0 stands in its back corner, out of the ball's way.
func _stand_aside(match_node: PongMatch) -> void:
	var court: PongCourt = match_node.court
	match_node.controllers[0].intent.avatar = court.clamp_avatar(
		0, Vector3(court.half_width, 0.0, court.half_length)
	)


func _saw(type: PongServoFacts.PongEventType, player: int) -> bool:
	return PongTestEvents.saw(_events, type, player)


func _ball_in(territory: int) -> bool:
	var state: PongState = PongServo.shared().get_state()
	return PongCourt.territory_of(state.ball_position) == territory


# The device player's running effect of [param kind] in the servo, or null.
func _servo_effect(kind: String) -> PongEffectState:
	return PongServo.effect_in(PongServo.shared().get_state(), kind)


func test_a_match_started_while_the_servo_runs_holds_its_state_before_the_first_update() -> void:
	# The servo's clock runs on from match to match in a window: a guest who rejoined a
	# network match streamed its first frame's pose stamped 0 s, the host aged it as the
	# fastest path, refused every later stamp (73 s) as one its clock could not have made,
	# and disconnected the player.
	_pong = PongTestScreen.stepped()
	_pong.stepped = false
	add_child(_pong)
	await get_tree().create_timer(1.0).timeout
	await _free_pong()
	var later: PongScreen = PongTestScreen.stepped()
	later.stepped = false
	_pong = later
	add_child(later)
	var servo_s: float = PongServo.shared().get_state().time_s
	assert_gt(servo_s, 0.5, "the servo's clock ran on in real time")
	assert_almost_eq(later.match_node.snapshot.time_s, servo_s, 0.1, "the new match's state")
