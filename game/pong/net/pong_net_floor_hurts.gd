class_name PongNetFloorHurts
extends RefCounted
## Floor bounces that cost health in a networked match. The ball's master sees the bounce
## in its servo; a client master claims it from the server ([code]_claim[/code]: epoch,
## victim), the server, the authority, judges the claim against the ball's path as its own
## servo ran it ([PongNetHurtJudge]) and charges what it accepts: the health loss goes to
## every peer ([code]_hurt[/code]: epoch, victim, "floor"), the master included, and every
## peer applies the server's hurts and no one else's, in the server's order. A claim that
## cannot be true (no such bounce here, a bounce charged already, faster than a ball can
## bounce, from a peer that was not the master at its epoch) is refused and counted against
## the sender. The server's own bounces as master are charged at once.

var judge: PongNetHurtJudge = null

var _wire: PongNetWire = null
var _match: PongMatch = null
var _authority: PongNetAuthority = null
var _report: PongNetReport = null
var _reject: Callable = Callable()
# Claims waiting for their bounce to show in our path: [sender, epoch, victim, arrived at].
var _pending: Array[Array] = []
# When (match seconds) this peer first saw each epoch, and the last epoch it saw.
var _epoch_from: Dictionary[int, float] = {}
var _seen_epoch: int = 0


## Follows [param p_match]; sends through [param wire]; [param p_reject] as
## [PongNetWeapons] takes it.
func _init(
	wire: PongNetWire,
	p_match: PongMatch,
	authority: PongNetAuthority,
	report: PongNetReport,
	p_reject: Callable
) -> void:
	_wire = wire
	_match = p_match
	_authority = authority
	_report = report
	_reject = p_reject
	judge = PongNetHurtJudge.new(_match.court, _authority.owners.size())


## An event of our servo: a floor bounce is recorded (server) and, when we are the
## master, charged (server) or claimed (client).
func on_event(event: PongEvent) -> void:
	if event.type != PongServoFacts.PongEventType.FLOOR:
		return
	var territory: int = event.territory
	var on_server: bool = _is_server()
	var ours: bool = _authority.is_master() and territory >= 0 and territory < judge.seats
	if on_server:
		judge.observe_floor(_match.now, event.position, ours)
	if not ours or _match.rules.is_over():
		return
	if on_server:
		_charge(_authority.epoch, territory)
	else:
		_wire.send_to(PongNetAuthority.SERVER_ID, &"_claim", [_authority.epoch, territory])


## Each frame on the server: the ball's path, and the claims that were waiting for it.
func observe(snapshot: PongState) -> void:
	if not _is_server():
		return
	for epoch: int in range(_seen_epoch + 1, _authority.epoch + 1):
		_epoch_from[epoch] = _match.now
	_seen_epoch = maxi(_seen_epoch, _authority.epoch)
	var master: bool = _authority.is_master()
	judge.observe(_match.now, snapshot.ball_position, snapshot.ball_velocity, master)
	_settle()


## Server: [param sender] claims that a floor bounce at [param epoch] cost [param victim].
func on_claim(sender: int, epoch: Variant, victim: Variant) -> void:
	if not _is_server():
		return
	var reason: String = PongNetProtocol.check_int(epoch, 1, _authority.epoch, "epoch")
	if reason.is_empty():
		reason = PongNetProtocol.check_int(victim, 0, judge.seats - 1, "victim")
	if not reason.is_empty():
		_reject.call(sender, "floor claim", reason)
		return
	var at_epoch: int = epoch
	var seat: int = victim
	if _authority.master_at(at_epoch) != sender:
		var why: String = "peer %d was not the master at epoch %d" % [sender, at_epoch]
		_reject.call(sender, "floor claim", why)
		return
	_pending.append([sender, at_epoch, seat, _match.now])
	_settle()


## A health loss the server charged ([param sender] must be the server).
func on_hurt(sender: int, epoch: Variant, player: Variant, cause: Variant) -> void:
	var reason: String = ""
	if sender != PongNetAuthority.SERVER_ID:
		reason = "only the server charges floor bounces"
	if reason.is_empty():
		reason = PongNetProtocol.check_int(epoch, 0, _authority.epoch, "epoch")
	if reason.is_empty():
		reason = PongNetProtocol.check_int(player, 0, judge.seats - 1, "player")
	if reason.is_empty() and (typeof(cause) != TYPE_STRING or cause != "floor"):
		reason = "cause %s is not one the network carries" % str(cause).left(32)
	if not reason.is_empty():
		_reject.call(sender, "hurt", reason)
		return
	var at_epoch: int = epoch
	var victim: int = player
	_apply(at_epoch, victim)


func _is_server() -> bool:
	return _authority.my_id == PongNetAuthority.SERVER_ID


func _settle() -> void:
	var waiting: Array[Array] = []
	for claim: Array in _pending:
		var epoch: int = claim[1]
		var victim: int = claim[2]
		var territory: int = _authority.territory_at(epoch)
		var arrived: float = claim[3]
		var from: float = _epoch_from.get(epoch, -INF)
		var to: float = _epoch_from.get(epoch + 1, INF)
		var verdict: Array = judge.judge(_match.now, arrived, victim, territory, from, to)
		match verdict[0]:
			PongNetHurtJudge.Verdict.ACCEPT:
				_charge(epoch, victim)
			PongNetHurtJudge.Verdict.WAIT:
				waiting.append(claim)
			_:
				_reject.call(claim[0], "floor claim", verdict[1])
	_pending = waiting


# Server: [param victim] loses a floor point, here and on every peer.
func _charge(epoch: int, victim: int) -> void:
	if _match.rules.is_over():
		return
	_wire.send_all(&"_hurt", [epoch, victim, "floor"])
	_apply(epoch, victim)


func _apply(epoch: int, victim: int) -> void:
	_match.rules.hurt(victim, PongRules.CAUSE_FLOOR)
	_report.hurts.append([epoch, victim, "floor"])
