extends "res://tests/pong/pong_screen_suite.gd"
## The fixture of the play suites: one peer of a real stepped match (the host, seat 0; the
## client, peer 42, drives seat 1, whose paddle comes over the network) without sockets.
## Received messages reach it as bytes through its router ([method _receive]), with their
## sender's id, as from the network; what this peer sends is recorded; the test driver's
## report counts what happened.

const PongTestScreen := preload("res://tests/pong/pong_test_screen.gd")
const NetReport := preload("res://tests/net/driver/net_report.gd")
const HOST: int = 1
const CLIENT: int = 42


## A router that records what this peer sends instead of sending it.
class RecordingRouter:
	extends PongNetRouter

	var sent: Array[PongNetMessage] = []
	## What the server forwarded: [origin, message] each.
	var forwards: Array[Array] = []

	func send_all(message: PongNetMessage, _copies: int = 1) -> void:
		sent.append(message)

	func forward(origin: int, message: PongNetMessage) -> void:
		forwards.append([origin, message])

	func send_to(_peer: int, message: PongNetMessage) -> void:
		sent.append(message)

	## What was sent of the layout [param schema_id], in order.
	func sent_of(schema_id: int) -> Array[PongNetMessage]:
		var out: Array[PongNetMessage] = []
		for message: PongNetMessage in sent:
			if message.encode().decode_u32(0) == schema_id:
				out.append(message)
		return out


var _play: PongNetPlay = null
var _router: RecordingRouter = null
var _report: NetReport = null


func after_each() -> void:
	if _play != null and is_instance_valid(_play):
		_play.queue_free()
	_play = null
	await _free_pong()


## The host's play, begun; null (and a failure) without the Pong renderer. [param me] and
## [param owners]: another peer's play (a client's, when [param me] is not the host).
func _open_play(
	me: int = HOST, owners: PackedInt64Array = PackedInt64Array([HOST, CLIENT])
) -> PongNetPlay:
	if not assert_true(PongServo.shared().is_available(), "the extension has the Pong renderer"):
		return null
	_pong = PongTestScreen.stepped()
	add_child(_pong)
	var match_node: PongMatch = _pong.match_node
	var remote: PongNetRemotePlayer = PongNetRemotePlayer.new(1)
	remote.intent = match_node.controllers[1].intent
	match_node.controllers[1] = remote
	(match_node.controllers[0] as PongAi).use_weapons = false
	_play = PongNetPlay.new()
	var session: PongNetSession = PongNetSession.new()
	session.is_server = me == HOST
	_play.session = session
	add_child(_play)
	_play.add_child(session)
	_router = RecordingRouter.new()
	_router.session = session
	session.add_child(_router)
	session.router = _router
	_report = NetReport.new()
	_report.watch(_play)
	var mine: PackedInt32Array = PackedInt32Array()
	for seat: int in owners.size():
		if owners[seat] == me:
			mine.append(seat)
	_play.begin(match_node, PongNetAuthority.new(me, owners), mine)
	_report.begin(_play)
	# These tests step the match's time by hand and stall nothing: the judge's clock is it.
	var stepped_match: PongMatch = match_node
	_play.floor_hurts.clock = func() -> float: return stepped_match.now
	return _play


## The host's play stepped as in a networked match (the master's word on floor bounces, not
## this servo's), its opening serve made, then the ball handed to the client lying at a spot
## of the client's territory (returned); the serves sent are left in the router's record.
## Null (and a failure) without the Pong renderer.
func _open_with_the_ball_at_the_client(frame_s: float) -> Variant:
	if _open_play() == null:
		return null
	_play.stepped = true
	_play.ball.stepped = true
	var match_node: PongMatch = _play.match_node
	match_node.rules_from_events = false
	var court: PongCourt = match_node.court
	var rest: Vector3 = Vector3(0.3, court.ball_radius, -court.half_length * 0.6)
	if court.territory_at(rest) != 1:
		rest.z = -rest.z
	assert_eq(court.territory_at(rest), 1, "a spot in the client's territory")
	for frame: int in 240:
		_play.frame(frame_s)
		if not _router.sent_of(PongNetTransferMessage.SCHEMA_ID).is_empty():
			break
	var handoff: PongNetTransferMessage = PongNetTransferMessage.new()
	handoff.epoch = _play.authority.epoch + 1
	handoff.kind = PongNetFacts.TransferKind.HANDOFF
	handoff.territory = 1
	handoff.master = CLIENT
	handoff.position = rest
	_receive(HOST, handoff)
	return rest


## [param message] reaches this peer from [param sender]: its bytes, through the router.
func _receive(sender: int, message: PongNetMessage) -> void:
	_router.receive(sender, message.encode())


## How many bad messages of [param what] this peer counted.
func _refused(what: String) -> int:
	return _report.refused.get(what, 0)


static func _bullet(
	seat: int, id: int, origin: Vector3, direction: Vector3, time_s: float
) -> PongNetBulletMessage:
	var bullet: PongNetBulletMessage = PongNetBulletMessage.new()
	bullet.seat = seat
	bullet.id = id
	bullet.origin = origin
	bullet.direction = direction
	bullet.time_s = time_s
	return bullet


static func _mine(seat: int, id: int, position: Vector3) -> PongNetMineMessage:
	var mine: PongNetMineMessage = PongNetMineMessage.new()
	mine.seat = seat
	mine.id = id
	mine.position = position
	return mine


static func _weapon_hurt(
	victim: int, cause: PongNetFacts.WeaponCause, seat: int, id: int
) -> PongNetWeaponHurtMessage:
	var hurt: PongNetWeaponHurtMessage = PongNetWeaponHurtMessage.new()
	hurt.victim = victim
	hurt.cause = cause
	hurt.seat = seat
	hurt.id = id
	return hurt
