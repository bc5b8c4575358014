extends Node
## A misbehaving peer for the fault tests (tests/net/test_net_guard.py starts this scene): it
## joins like the game's networked-Pong command line ([PongNetCli], the same arguments) and,
## once its match runs, does what [code]--rogue=MODE[/code] says, through the same RPC
## surface as an honest peer:
## [br]- [code]bad[/code] (default): every kind of malformed or unauthorised message, and
## calls with the wrong number of arguments. The server must drop each, log the peer once,
## disconnect it at the budget, and play on.
## [br]- [code]forge[/code]: the issue's cheat: while it is the ball's master it claims
## [constant FORGED] floor bounces that cost the host's seat a point (and tells every peer so
## directly). None may cost the host anything.
## [br]- [code]mark[/code]: plays honestly and prints [constant HIT_MARK] each time its own
## paddle hits the ball while it is the master, once the match is past its loading stall:
## the test kills it right then.
## A test tool, out of every export: under tests/ (no export preset takes it), and in a
## folder Godot does not scan (.gdignore), since an export lists the path of every file the
## scan gave a uid. The harness runs it by path.

## Rounds of bad messages: unreliable ones may be dropped by ENet's throttle in a burst.
const ROUNDS: int = 3
## Match seconds before the first round, and between rounds.
const FIRST_S: float = 1.0
const EVERY_S: float = 0.5
## Forged floor claims in all, and at most this many a frame.
const FORGED: int = 120
const FORGED_PER_FRAME: int = 10
const HIT_MARK: String = "PongNet rogue: my paddle hit the ball, I am the master"
## Match seconds before a hit is marked: past the court's loading stall, and its first beat.
const MARK_AFTER_S: float = 3.0

var _cli: PongNetCli = PongNetCli.new()
var _mode: String = "bad"
var _match_clock: float = -1.0
var _rounds: int = 0
var _forged: int = 0


func _ready() -> void:
	_mode = PongNetCli.parse(OS.get_cmdline_user_args()).get("rogue", "bad")
	add_child(_cli)
	# After the command line's own deferred launch, which makes its PongNet.
	_follow.call_deferred()


func _follow() -> void:
	if _cli.net != null:
		_cli.net.match_started.connect(_on_match_started)


func _on_match_started() -> void:
	_match_clock = 0.0
	if _mode == "mark":
		_cli.net.play.match_node.event_seen.connect(_on_event)


func _process(delta: float) -> void:
	if _match_clock < 0.0 or not _cli.net.play.is_running():
		return
	_match_clock += delta
	if _mode == "forge":
		_forge(_cli.net.play)
	elif _mode == "bad" and _rounds < ROUNDS and _match_clock > FIRST_S + EVERY_S * _rounds:
		_rounds += 1
		attack(_cli.net.play)


func _on_event(event: PongEvent) -> void:
	var play: PongNetPlay = _cli.net.play
	if event.type != PongServoFacts.PongEventType.PADDLE or not play.authority.is_master():
		return
	if event.player == _cli.net.my_seat() and _match_clock > MARK_AFTER_S:
		print("%s (match second %.2f)" % [HIT_MARK, _match_clock])


# While master: claims that the host's seat (not the ball's territory) lost points.
func _forge(play: PongNetPlay) -> void:
	if _forged >= FORGED or not play.authority.is_master():
		return
	var host_seat: int = 0
	for _claim_index: int in FORGED_PER_FRAME:
		play._claim.rpc_id(PongNetAuthority.SERVER_ID, play.authority.epoch, host_seat)
		play._hurt.rpc(play.authority.epoch, host_seat, "floor")
		_forged += 1
	print("PongNet rogue: %d forged floor hurts sent" % _forged)


## Sends the bad messages from [param play]'s peer.
static func attack(play: PongNetPlay) -> void:
	var far: Vector3 = Vector3(0.0, 1.0, 0.0)
	var me: int = play.authority.my_id
	var not_mine: int = 0 if play.authority.owner_of(0) != me else 1
	print("PongNet rogue: sending bad messages")
	# Wrong types.
	play._ball.rpc("one", 2, 3.0, far, far, far, 0)
	play._pose.rpc(0, "avatar", far, far, Vector3.UP, 0, 1.0, 0)
	# Out of range: a ball far outside the court, a non-finite velocity, a bad seat.
	play._ball.rpc(play.authority.epoch, 1 << 20, 1.0, Vector3(99, 99, 99), far, far, 0)
	play._ball.rpc(play.authority.epoch, 1 << 21, 1.0, far, Vector3(NAN, 0, 0), far, 0)
	play._pose.rpc(7, far, Vector3.ZERO, Vector3.ZERO, Vector3.UP, 0, 1.0, 0)
	play._pose.rpc(1 - not_mine, far, Vector3.ZERO, Vector3.ZERO, Vector3.UP, 0, 1.0, -5)
	# No authority: a ball state while not the master, a pose for another's seat, a transfer
	# (only the server issues them), a health loss (only the server charges them), a
	# hand-off request, owners.
	play._ball.rpc(play.authority.epoch, 1 << 22, 1.0, far, Vector3.ZERO, Vector3.ZERO, 0)
	play._pose.rpc(not_mine, far, Vector3.ZERO, Vector3.ZERO, Vector3.UP, 0, 1.0, 0)
	play._transfer.rpc(play.authority.epoch + 50, 1, 0, me, far, Vector3.ZERO, Vector3.ZERO, 0)
	play._hurt.rpc(0, not_mine, "floor")
	play._request.rpc_id(1, play.authority.epoch + 7, 0, far, Vector3.ZERO, Vector3.ZERO)
	play._owners.rpc(PackedInt64Array([me, me]))
	# Oversized: a 64 KiB name.
	play._hurt.rpc(play.authority.epoch, 0, "x".repeat(65536))
	# The wrong number of arguments, which the engine itself would fail with an error line
	# per call: too few, too many, none.
	play.rpc(&"_hurt", 1)
	play.rpc(&"_claim", 1, 2, 3, 4)
	play.rpc(&"_pose")
	play.get_parent().rpc(&"_ready_up", true, false)
	_attack_weapons(play, not_mine)


# Bullets, mines and weapon hurts: each a wrong type, out of range, or without authority.
static func _attack_weapons(play: PongNetPlay, not_mine: int) -> void:
	var mine: int = 1 - not_mine
	var far: Vector3 = Vector3(0.0, 1.0, 0.0)
	var theirs: Vector3 = Vector3(0.2, 0.0, 1.5 if mine == 1 else -1.5)
	play._bullet.rpc("zero", 0, far, Vector3.UP, 1.0)
	play._bullet.rpc(mine, 1 << 27, Vector3(99, 99, 99), Vector3.UP, 1.0)
	play._bullet.rpc(not_mine, 1 << 27, far, Vector3.UP, 1.0)
	# A fresh number, then the same one again, then the next one at once (cooldown).
	var shot: int = (1 << 28) + roundi(play.match_node.now * 10.0)
	play._bullet.rpc(mine, shot, far, Vector3.UP, 1e6 + play.match_node.now)
	play._bullet.rpc(mine, shot, far, Vector3.UP, 1e6 + play.match_node.now + 1.0)
	play._bullet.rpc(mine, shot + 1, far, Vector3.UP, 1e6 + play.match_node.now + 0.01)
	play._mine.rpc(mine, 0, "here", "slow")
	play._mine.rpc(mine, 2, theirs, "slow")
	play._mine.rpc(not_mine, 3, -theirs, "none")
	play._weapon_hurt.rpc(not_mine, "bullet", mine, 0)
	play._weapon_hurt.rpc(mine, "bullet", not_mine, 1 << 29)
	play._weapon_hurt.rpc(mine, "x".repeat(65536), not_mine, 0)
