extends "res://tests/pong/pong_screen_suite.gd"
## The match the menu starts against the computer (Easy, beginner mode), with the person's
## paddle on the simulated device as in the game: an idle hand gets a serve at once and a
## ball that keeps coming and going; the clumsy first-time player (pong_clumsy_player.gd),
## moving that paddle with the mouse and walking with the keys (pong_mouse_hand.gd), plays
## a rally of [constant MIN_RALLY] paddle contacts (back and forth) within [constant PLAY_S]
## seconds, whichever of [constant HANDS] it is.
## Match time throughout: the match is stepped.

## Runs scenes or processes for seconds: make check (--quick) leaves it out.
const SLOW := true
const PongTestScreen := preload("res://tests/pong/pong_test_screen.gd")
const PongMouseHand := preload("res://tests/pong/pong_mouse_hand.gd")
const PLAY_S: float = 120.0
## The clumsy hands' seeds: several newcomers, each of whom must get a rally.
const HANDS: Array[int] = [1, 2, 3, 4, 5]
const MIN_RALLY: int = 6
## A serve this soon after the start: a person waits no longer.
const FIRST_SERVE_S: float = 5.0
## How long an idle hand watches.
const IDLE_S: float = 60.0
## The ball may be still at most this share of the idle hand's match after the first serve:
## between rallies, not as the match's usual state.
const MAX_STILL_SHARE: float = 0.25


## What the ball did in a match: its serves, paddle contacts and the longest rally, and
## how long it was still.
class Watch:
	extends RefCounted
	var first_serve_s: float = -1.0
	var contacts: int = 0
	var longest: int = 0
	var still_s: float = 0.0
	var watched_s: float = 0.0
	var _rally: int = 0
	var _last_player: int = -1

	func serve(_receiver: int, now: float) -> void:
		if first_serve_s < 0.0:
			first_serve_s = now
		_end_rally()

	func see(event: PongEvent) -> void:
		if event.type == PongServoFacts.PongEventType.PADDLE:
			contacts += 1
			# The same paddle twice in a row is one return: a rally goes back and forth.
			if event.player != _last_player:
				_last_player = event.player
				_rally += 1
				longest = maxi(longest, _rally)
		elif event.type == PongServoFacts.PongEventType.FLOOR:
			_end_rally()
		elif event.type == PongServoFacts.PongEventType.WALL and event.back_wall_of >= 0:
			_end_rally()

	func sample(velocity: Vector3, dt: float) -> void:
		if first_serve_s < 0.0:
			return
		watched_s += dt
		if velocity.length() < PongReferee.STALL_SPEED_M_PER_S:
			still_s += dt

	func still_share() -> float:
		return still_s / maxf(watched_s, 1e-6)

	func _end_rally() -> void:
		_rally = 0
		_last_player = -1


func test_an_idle_hand_gets_a_serve_at_once_and_a_ball_that_keeps_moving() -> void:
	set_timeout(120.0)
	var match_node: PongMatch = _start_default_match()
	if match_node == null:
		return
	var watch: Watch = _watch(match_node)
	var look: Callable = func() -> bool:
		watch.sample(match_node.snapshot.ball_velocity, PongMatch.STEP_CHUNK_S)
		return false
	match_node.run_until(look, IDLE_S)
	print(
		(
			(
				"    idle hand, %.0f s: first serve at %.1f s, ball still %.0f %% of the time after"
				+ " it, %d paddle contacts, longest rally %d"
			)
			% [
				match_node.now,
				watch.first_serve_s,
				watch.still_share() * 100.0,
				watch.contacts,
				watch.longest
			]
		)
	)
	assert_true(watch.first_serve_s >= 0.0, "a serve")
	assert_lt(watch.first_serve_s, FIRST_SERVE_S, "within %.0f s of the start" % FIRST_SERVE_S)
	assert_lt(watch.still_share(), MAX_STILL_SHARE, "the ball does not sit")


func test_clumsy_hands_on_the_mouse_rally_within_two_minutes() -> void:
	set_timeout(900.0)
	var rallied_at: Array[float] = []
	for seed_value: int in HANDS:
		var match_node: PongMatch = _start_default_match()
		if match_node == null:
			return
		var watch: Watch = _watch(match_node)
		var hand: PongMouseHand = PongMouseHand.new(match_node, seed_value)
		var human: PongHumanPlayer = match_node.controllers[0] as PongHumanPlayer
		var start: Vector3 = human.intent.avatar
		# How far the mouse moved the hand and the keys the avatar, at most.
		var moved: Array[float] = [0.0, 0.0]
		var play: Callable = func() -> bool:
			hand.act(PongMatch.STEP_CHUNK_S)
			moved[0] = maxf(moved[0], human.hand.length())
			moved[1] = maxf(moved[1], human.intent.avatar.distance_to(start))
			return watch.longest >= MIN_RALLY
		var rallied: bool = match_node.run_until(play, PLAY_S)
		hand.release()
		rallied_at.append(match_node.now if rallied else -1.0)
		print(
			(
				"    clumsy hand %d on the mouse: %d paddle contacts by %.0f s, longest rally %d"
				% [seed_value, watch.contacts, match_node.now, watch.longest]
			)
		)
		assert_gt(moved[0], 0.1, "(the test's own check: the mouse moves the hand)")
		assert_gt(moved[1], 0.1, "(the test's own check: the keys walk the avatar)")
		await _free_pong()
	for i: int in HANDS.size():
		assert_true(
			rallied_at[i] >= 0.0,
			"hand %d: a rally of %d within %.0f s" % [HANDS[i], MIN_RALLY, PLAY_S]
		)


# The screen as the menu's Play against the computer starts it, stepped by the test; null
# (and a failure) without the Pong renderer or when the person's paddle is not the device's.
func _start_default_match() -> PongMatch:
	if not assert_true(PongServo.shared().is_available(), "the extension has the Pong renderer"):
		return null
	_pong = PongTestScreen.stepped(PongMatch.Mode.VS_COMPUTER, 2, PongRules.DEFAULT_START_HEALTH)
	(_pong.get_node(^"Match") as PongMatch).auto_serve = true
	_pong.beginner = PongSetup.BEGINNER_FIRST
	add_child(_pong)
	var match_node: PongMatch = _pong.match_node
	var human: PongHumanPlayer = match_node.controllers[0] as PongHumanPlayer
	var on_device: bool = human != null and not human.kinematic and match_node.local_player == 0
	if not assert_true(on_device, "(the test's own check: the person's paddle is the device's)"):
		return null
	assert_eq(match_node.difficulty, PongAiLevel.Level.EASY, "(the default level)")
	return match_node


func _watch(match_node: PongMatch) -> Watch:
	var watch: Watch = Watch.new()
	match_node.served.connect(func(receiver: int) -> void: watch.serve(receiver, match_node.now))
	match_node.event_seen.connect(watch.see)
	return watch
