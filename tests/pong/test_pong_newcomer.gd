extends "res://tests/pong/pong_screen_suite.gd"
## A first-time player's match: the scripted clumsy player (pong_clumsy_player.gd: late,
## shaky, slow, no plan) rallies against the default computer in a real match as the setup
## starts it (the Easy computer, beginner mode, the computer's weapons on) for
## [constant PLAY_S] simulated seconds, touching the ball often
## enough and keeping rallies going (the figures are printed for the notes); the computer
## keeps its gun and mines away for the first seconds; a thrown mine never lands on a
## standing player.
##
## The targets: a newcomer enjoys a game in which the ball keeps coming back. So the clumsy
## player must touch at least [constant MIN_TOUCHED_SHARE] of the balls that come into its
## half (it then returns most of them), and within the first two minutes play at least one
## rally of [constant MIN_LONGEST_RALLY] paddle contacts (both sides counted: it returns the
## ball three times in a row), the point at which Pong feels like a rally and not a serve
## and a miss.

## Runs scenes or processes for seconds: make check (--quick) leaves it out.
const SLOW := true


## The match's paddle contacts and balls, from its events.
class Tally:
	extends RefCounted
	## The clumsy player's (player 0's) paddle contacts.
	var own: int = 0
	## How often the ball came into its half: serves to it, and balls played across.
	var balls_in: int = 0
	## The longest rally, paddle contacts of both sides between a serve or a floor bounce and
	## the next one.
	var longest: int = 0
	var rallies: Array[int] = []
	var _rally: int = 0
	# A serve to player 0 was counted: the territory event it may raise is the same ball.
	var _served_in: bool = false

	func count(event: PongEvent) -> void:
		match event.type:
			PongServoFacts.PongEventType.PADDLE:
				_rally += 1
				own += 1 if event.player == 0 else 0
			PongServoFacts.PongEventType.TERRITORY:
				balls_in += 1 if event.territory == 0 and not _served_in else 0
				_served_in = false
			PongServoFacts.PongEventType.FLOOR:
				end_rally()

	func serve(receiver: int) -> void:
		end_rally()
		if receiver == 0:
			balls_in += 1
			_served_in = true

	func end_rally() -> void:
		if _rally > 0:
			rallies.append(_rally)
		longest = maxi(longest, _rally)
		_rally = 0

	func mean_rally() -> float:
		var sum: int = 0
		for length: int in rallies:
			sum += length
		return float(sum) / maxi(rallies.size(), 1)


const PongTestScreen := preload("res://tests/pong/pong_test_screen.gd")
const PongClumsyPlayer := preload("res://tests/pong/pong_clumsy_player.gd")
const PongTestCourt := preload("res://tests/pong/pong_test_court.gd")
const PLAY_S: float = 120.0
const MIN_TOUCHED_SHARE: float = 0.5
const MIN_LONGEST_RALLY: int = 6


func test_a_clumsy_first_time_player_rallies_against_the_default_computer() -> void:
	set_timeout(240.0)
	if not assert_true(PongServo.shared().is_available(), "the extension has the Pong renderer"):
		return
	_pong = PongTestScreen.stepped(PongMatch.Mode.VS_COMPUTER, 2, PongRules.DEFAULT_START_HEALTH)
	var match_node: PongMatch = _pong.get_node(^"Match") as PongMatch
	match_node.auto_serve = true
	_pong.beginner = PongSetup.BEGINNER_FIRST
	add_child(_pong)
	match_node.controllers[0] = PongClumsyPlayer.new(0, match_node.court, match_node.reach, 7)
	var tally: Tally = Tally.new()
	match_node.event_seen.connect(tally.count)
	match_node.served.connect(tally.serve)
	match_node.run_until(match_node.rules.is_over, PLAY_S)
	tally.end_rally()
	var minutes: float = match_node.now / 60.0
	var touched: float = float(tally.own) / maxi(tally.balls_in, 1)
	var lost: int = match_node.rules.start_health - match_node.rules.get_health(0)
	print(
		(
			(
				"    clumsy player vs the default computer, %.0f s: %d paddle contacts, %d balls"
				+ " came into its half (%.0f %% touched), %.1f contacts/min, longest rally %d"
				+ " paddle contacts, mean rally %.1f, health lost %d (%.1f/min), computer's %d"
			)
			% [
				match_node.now,
				tally.own,
				tally.balls_in,
				touched * 100.0,
				tally.own / maxf(minutes, 1e-6),
				tally.longest,
				tally.mean_rally(),
				lost,
				lost / maxf(minutes, 1e-6),
				match_node.rules.start_health - match_node.rules.get_health(1),
			]
		)
	)
	assert_gt(tally.balls_in, 10, "(the test's own check: the ball came to it)")
	assert_true(touched >= MIN_TOUCHED_SHARE, "it touches at least half the balls it gets")
	assert_true(tally.longest >= MIN_LONGEST_RALLY, "a rally of %d contacts" % MIN_LONGEST_RALLY)


func test_the_computer_keeps_its_weapons_away_at_first() -> void:
	if not assert_true(PongServo.shared().is_available(), "the extension has the Pong renderer"):
		return
	_pong = PongTestScreen.stepped(PongMatch.Mode.VS_COMPUTER, 2, PongRules.DEFAULT_START_HEALTH)
	var match_node: PongMatch = _pong.get_node(^"Match") as PongMatch
	match_node.auto_serve = true
	add_child(_pong)
	var computer: PongAi = match_node.controllers[1] as PongAi
	var armed_at: Array[float] = []
	var watch: Callable = func() -> bool:
		if armed_at.is_empty() and (computer.intent.gun or match_node.mines.left(1) < 4):
			armed_at.append(match_node.now)
		return false
	match_node.run_until(watch, PongMatch.WEAPONS_GRACE_S + 20.0)
	if not assert_false(armed_at.is_empty(), "(the test's own check: it arms in the end)"):
		return
	print("    the computer first drew its gun or threw a mine at %.1f s" % armed_at[0])
	assert_true(armed_at[0] >= PongMatch.WEAPONS_GRACE_S, "not in the first seconds")


func test_a_thrown_mine_never_lands_on_a_standing_player() -> void:
	var court: PongCourt = PongTestCourt.make()
	var mines: PongMines = PongMines.new()
	# Both at home on the centre line: the mirror of the thrower's spot is the victim's.
	var thrower: Vector3 = court.clamp_avatar(1, court.toward_back_wall(1, 0.6))
	var victim: Vector3 = court.clamp_avatar(0, court.toward_back_wall(0, 0.6))
	var standing: Array[Vector3] = [victim]
	var landed: Array[PongMines.Mine] = []
	for throw: int in PongMines.KINDS.size():
		var mine: PongMines.Mine = mines.place(1, thrower, court, standing)
		if mine != null:
			landed.append(mine)
	assert_gt(landed.size(), 1, "more than one mine lands from the same spot")
	for mine: PongMines.Mine in landed:
		var gap: float = Vector2(mine.position.x - victim.x, mine.position.z - victim.z).length()
		var clear: bool = gap >= PongMines.CLEAR_OF_PLAYERS_M - 1e-3
		assert_true(clear, "the %s mine lands beside the player, not under" % mine.kind)
		assert_eq(PongCourt.territory_of(mine.position), 0, "in the victim's half")
	# Away from everyone the throw's rule is unchanged: the mirror of the thrower's spot.
	var aside: Vector3 = Vector3(1.0, 0.0, -1.5)
	var far: PongMines.Mine = PongMines.new().place(1, aside, court, standing)
	if assert_not_null(far, "a mine away from everyone lands"):
		assert_almost_eq(far.position, Vector3(1.0, 0.0, 1.5), 1e-6, "at the mirror spot")
