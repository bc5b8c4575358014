extends "res://tests/net/driver/net_peer.gd"
## A misbehaving peer for the fault tests (tests/net/test_net_guard.py starts this scene): it
## joins like every test peer (the game's networked-Pong command line under the test driver,
## the same arguments) and, once its match runs, does what [code]--rogue=MODE[/code] says,
## through the same raw-packet path as an honest peer ([method SceneMultiplayer.send_bytes],
## which [PongNetRouter] uses):
## [br]- [code]bad[/code] (default): every kind of bad bytes ([method attack]): too short,
## cut off, with bytes left over, unknown layouts, fields outside the schema's limits, NaN,
## huge strings, messages only the server may send, messages only the server may take,
## messages about seats it does not drive, a flood. The server must drop each, log the peer
## once, disconnect it at the budget, write no engine error, and play on.
## [br]- [code]forge[/code]: the issue's cheat: while it is the ball's master it claims
## [constant FORGED] floor bounces that cost the host's seat a point (and tells every peer so
## directly). None may cost the host anything.
## [br]- [code]forge-ball[/code]: the issue's second cheat: once the ball's master, it stops
## its real stream and streams a ball of its own making instead, bouncing in the other seat's
## territory every [constant FORGED_BOUNCE_S] (states consistent among themselves, newer than
## the real stream's), and claims each bounce. The server's check of the ball must refuse
## every state and claim and disconnect it at the budget.
## [br]- [code]mute[/code]: the griefer: whenever it is the ball's master it streams nothing
## and never hands the ball over (its heartbeat goes on), printing [constant MUTE_MARK] once
## an epoch. The server must take the ball and count it; the rally must go on.
## [br]- [code]mark[/code]: plays honestly and prints [constant HIT_MARK] each time its own
## paddle hits the ball while it is the master, once the match is past its loading stall:
## the test kills it right then.
## A test tool, out of every export: under tests/ (no export preset takes it), and in a
## folder Godot does not scan (.gdignore), since an export lists the path of every file the
## scan gave a uid. The harness runs it by path.

## Rounds of bad messages: unreliable ones may be lost on the way.
const ROUNDS: int = 3
## Match seconds before the first round, and between rounds.
const FIRST_S: float = 1.0
const EVERY_S: float = 0.5
## Forged floor claims in all, and at most this many a frame.
const FORGED: int = 120
const FORGED_PER_FRAME: int = 10
## The forged ball's bounce period, s, and where it bounces (in seat 0's territory; mirrored into
## seat 1's when the rogue drives seat 0).
const FORGED_BOUNCE_S: float = 0.6
const FORGED_SPOT: Vector3 = Vector3(0.4, 0.0, 1.5)
const HIT_MARK: String = "PongNet rogue: my paddle hit the ball, I am the master"
const MUTE_MARK: String = "PongNet rogue: the ball's master, streaming nothing"
## Match seconds before a hit is marked: past the court's loading stall, and its first beat.
const MARK_AFTER_S: float = 3.0
## Bad packets in the flood that ends each round.
const FLOOD: int = 40
const RELIABLE: MultiplayerPeer.TransferMode = MultiplayerPeer.TRANSFER_MODE_RELIABLE

var _mode: String = "bad"
var _rogue_clock: float = -1.0
var _rounds: int = 0
var _forged: int = 0
# forge-ball: seconds since it began, and the forged states sent.
var _forging_s: float = -1.0
var _forged_states: int = 0
var _forged_time: float = -INF
var _muted_epoch: int = -1


func _ready() -> void:
	super()
	_mode = option("rogue", "bad")


func _on_match_started() -> void:
	super()
	_rogue_clock = 0.0
	if _mode == "mark":
		cli.net.play.match_node.event_seen.connect(_on_event)


func _process(delta: float) -> void:
	super(delta)
	if _rogue_clock < 0.0 or cli == null or not cli.net.play.is_running():
		return
	_rogue_clock += delta
	if _mode == "forge":
		_forge(cli.net.play)
	elif _mode == "forge-ball":
		_forge_ball(cli.net.play, delta)
	elif _mode == "mute" and cli.net.play.authority.is_master():
		# A private member of the play, on purpose: the griefer's own build would neither
		# stream nor ask for the hand-off (the play does neither until a transfer has
		# settled, and one dated at no time never does).
		cli.net.play._transferred_at = INF
		if cli.net.play.authority.epoch != _muted_epoch:
			_muted_epoch = cli.net.play.authority.epoch
			print("%s (epoch %d)" % [MUTE_MARK, _muted_epoch])
	elif _mode == "bad" and _rounds < ROUNDS and _rogue_clock > FIRST_S + EVERY_S * _rounds:
		_rounds += 1
		attack(cli.net.play)


func _on_event(event: PongEvent) -> void:
	var play: PongNetPlay = cli.net.play
	if event.type != PongServoFacts.PongEventType.PADDLE or not play.authority.is_master():
		return
	if event.player == cli.net.my_seat() and _rogue_clock > MARK_AFTER_S:
		print("%s (match second %.2f)" % [HIT_MARK, _rogue_clock])


# While master: claims that the host's seat (not the ball's territory) lost points, and tells
# every peer it did (a floor hurt only the server may send).
func _forge(play: PongNetPlay) -> void:
	if _forged >= FORGED or not play.authority.is_master():
		return
	var claim: PongNetFloorClaimMessage = PongNetFloorClaimMessage.new()
	claim.epoch = play.authority.epoch
	claim.victim = 0
	var hurt: PongNetFloorHurtMessage = PongNetFloorHurtMessage.new()
	hurt.epoch = play.authority.epoch
	hurt.victim = 0
	for _claim_index: int in FORGED_PER_FRAME:
		play.session.router.send_to(PongNetAuthority.SERVER_ID, claim)
		play.session.router.send_all(hurt)
		_forged += 1
	print("PongNet rogue: %d forged floor hurts sent" % _forged)


# While master: its real stream stopped, a forged ball bouncing in the other seat's
# territory, each bounce claimed.
func _forge_ball(play: PongNetPlay, delta: float) -> void:
	if not play.authority.is_master():
		return
	# A private member of the play, on purpose: the cheat's own build would not stream.
	play._last_sent_time = INF
	# One state per servo step, as an honest stream sends them.
	if play.match_node.snapshot.time_s <= _forged_time:
		return
	_forged_time = play.match_node.snapshot.time_s
	var before: float = _forging_s
	_forging_s = maxf(_forging_s, 0.0) + delta
	var g: float = play.match_node.court.gravity
	var radius: float = play.match_node.court.ball_radius
	var up: float = 0.5 * g * FORGED_BOUNCE_S
	var since: float = fmod(_forging_s, FORGED_BOUNCE_S)
	var state: PongNetBallMessage = PongNetBallMessage.new()
	state.epoch = play.authority.epoch
	_forged_states += 1
	state.seq = (1 << 24) + _forged_states
	state.time_s = play.match_node.snapshot.time_s
	var victim: int = 1 - _mine(play)
	var spot: Vector3 = FORGED_SPOT * Vector3(1.0, 1.0, 1.0 if victim == 0 else -1.0)
	state.position = spot + Vector3(0.0, radius + up * since - 0.5 * g * since * since, 0.0)
	state.velocity = Vector3(0.0, up - g * since, 0.0)
	play.session.router.send_all(state)
	if before >= 0.0 and floori(_forging_s / FORGED_BOUNCE_S) > floori(before / FORGED_BOUNCE_S):
		var claim: PongNetFloorClaimMessage = PongNetFloorClaimMessage.new()
		claim.epoch = play.authority.epoch
		claim.victim = victim
		play.session.router.send_to(PongNetAuthority.SERVER_ID, claim)
	if _forged_states % 25 == 1:
		print("PongNet rogue: %d forged ball states sent" % _forged_states)


## Sends the bad messages from [param play]'s peer to the server, as raw packets.
static func attack(play: PongNetPlay) -> void:
	var api: SceneMultiplayer = play.multiplayer as SceneMultiplayer
	var send: Callable = func(bytes: PackedByteArray) -> void:
		api.send_bytes(
			bytes, PongNetAuthority.SERVER_ID, RELIABLE, PongNetFacts.NET_CHANNEL_RELIABLE
		)
	print("PongNet rogue: sending bad messages")
	for bytes: PackedByteArray in bad_bytes(play):
		send.call(bytes)
	# Messages only the server sends, and a pose for a seat this peer does not drive.
	for message: PongNetMessage in unauthorised(play):
		send.call(message.encode())
	# A flood of unknown layouts (the server has disconnected this peer by now).
	for i: int in FLOOD:
		send.call(PackedByteArray([0xEF, 0xBE, 0xAD, 0xDE, i & 0xFF]))


## Bytes that decode to no valid message: each fails the schema's checks.
static func bad_bytes(play: PongNetPlay) -> Array[PackedByteArray]:
	var out: Array[PackedByteArray] = []
	var ball: PongNetBallMessage = _ball(play)
	var good: PackedByteArray = ball.encode()
	out.append(PackedByteArray([1, 2, 3]))  # No layout id.
	out.append(good.slice(0, good.size() - 5))  # Cut off.
	out.append(good + PackedByteArray([0, 0, 0]))  # Bytes left over.
	var unknown: PackedByteArray = good.duplicate()
	unknown.encode_u32(0, 0xDEADBEEF)  # A layout of no message.
	out.append(unknown)
	# Out of the schema's range: a ball far outside any court, a NaN velocity, a leg of a
	# minute, a pose's seat 7, a bullet number past the limit, a mine's number 9.
	ball.position = Vector3(99.0, 99.0, 99.0)
	out.append(ball.encode())
	ball = _ball(play)
	ball.velocity = Vector3(NAN, 0.0, 0.0)
	out.append(ball.encode())
	ball = _ball(play)
	ball.leg_ms = 60000
	out.append(ball.encode())
	var pose: PongNetPoseMessage = _pose(play, 7)
	out.append(pose.encode())
	pose = _pose(play, _mine(play))
	pose.normal = Vector3(0.0, 0.0, 0.5)  # Not a unit vector.
	out.append(pose.encode())
	var bullet: PongNetBulletMessage = PongNetBulletMessage.new()
	bullet.seat = _mine(play)
	bullet.id = PongNetFacts.NET_MAX_WEAPON_ID + 1
	bullet.origin = Vector3(0.0, 1.0, 0.0)
	bullet.direction = Vector3.UP
	out.append(bullet.encode())
	var mine: PongNetMineMessage = PongNetMineMessage.new()
	mine.id = 9
	out.append(mine.encode())
	var hurt: PongNetWeaponHurtMessage = PongNetWeaponHurtMessage.new()
	var hurt_bytes: PackedByteArray = hurt.encode()
	hurt_bytes[5] = 7  # Its cause: no such weapon.
	out.append(hurt_bytes)
	# Huge strings: a hello of a 60 000-byte name (its count says so), and one whose count
	# claims more than the packet holds.
	var hello: PongNetHelloMessage = PongNetHelloMessage.new()
	hello.name = "x".repeat(60000)
	out.append(hello.encode())
	var short_hello: PackedByteArray = PongNetHelloMessage.new().encode()
	short_hello.encode_u16(4, 40000)
	out.append(short_hello)
	return out


## Messages that decode but are not this peer's to send: only the server's (a transfer, a
## floor hurt, owners, the lobby, a start, a refusal), and a pose and a bullet for a seat it
## does not drive.
static func unauthorised(play: PongNetPlay) -> Array[PongNetMessage]:
	var me: int = play.authority.my_id
	var transfer: PongNetTransferMessage = PongNetTransferMessage.new()
	transfer.epoch = play.authority.epoch + 50
	transfer.master = me
	var hurt: PongNetFloorHurtMessage = PongNetFloorHurtMessage.new()
	hurt.victim = 1 - _mine(play)
	var owners: PongNetOwnersMessage = PongNetOwnersMessage.new()
	owners.owners = PackedInt64Array([me, me])
	var start: PongNetStartMessage = PongNetStartMessage.new()
	start.owners = PackedInt64Array([me, me])
	start.health = 1
	var refusal: PongNetRefusalMessage = PongNetRefusalMessage.new()
	refusal.reason = "go away"
	var bullet: PongNetBulletMessage = PongNetBulletMessage.new()
	bullet.seat = 1 - _mine(play)
	bullet.id = 1 << 27
	bullet.origin = Vector3(0.0, 1.0, 0.0)
	bullet.direction = Vector3.UP
	bullet.time_s = 1.0
	var out: Array[PongNetMessage] = [transfer, hurt, owners, start, refusal, bullet]
	out.append(_pose(play, 1 - _mine(play)))
	out.append(PongNetLobbyMessage.new())
	return out


# The seat this peer drives.
static func _mine(play: PongNetPlay) -> int:
	return 0 if play.authority.owner_of(0) == play.authority.my_id else 1


static func _ball(play: PongNetPlay) -> PongNetBallMessage:
	var ball: PongNetBallMessage = PongNetBallMessage.new()
	ball.epoch = play.authority.epoch
	ball.seq = 1 << 20
	ball.time_s = 1.0
	ball.position = Vector3(0.0, 1.0, 0.0)
	return ball


static func _pose(play: PongNetPlay, seat: int) -> PongNetPoseMessage:
	var pose: PongNetPoseMessage = PongNetPoseMessage.new()
	pose.seat = seat
	pose.avatar = play.match_node.avatar_of(mini(seat, 1))
	pose.normal = Vector3.BACK
	pose.time_s = 1.0
	return pose
