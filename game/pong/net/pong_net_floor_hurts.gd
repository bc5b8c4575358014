class_name PongNetFloorHurts
extends RefCounted
## Floor bounces that cost health in a networked match. The ball's master sees the bounce
## in its servo; a client master claims it from the server ([PongNetFloorClaimMessage]: epoch,
## victim), the server, the authority, judges the claim against the ball's path as its own
## servo ran it ([PongNetHurtJudge]) and charges what it accepts: the health loss goes to
## every peer ([PongNetFloorHurtMessage]: epoch, victim), the master included, and every
## peer applies the server's hurts and no one else's (only the server sends them: the
## router), in the server's order. A claim that cannot be true (no such bounce here, a
## bounce charged already, faster than a ball can bounce, from a peer that was not the master
## at its epoch) is refused and counted against the sender. The server's own bounces as
## master are charged at once.
## [br]Its times are on [member clock], the clock messages are aged by, not the match's: the
## match's time stops growing while its process stalls (a frame counts for at most 0.1 s, a
## stepped peer catches up 0.1 s at most), and a bounce placed by its age on it slid out of
## its epoch (honest claims were refused so).

## A floor bounce cost [param victim] a point at [param epoch], here as on every peer.
signal hurt_applied(epoch: int, victim: int)
## This client, the master, claimed the floor bounce [param event] at [param epoch].
signal claimed(epoch: int, event: PongEvent)

var judge: PongNetHurtJudge = null
## The clock of the judge's times, seconds: this machine's ([method PongNetBall.clock_s]).
var clock: Callable = func() -> float: return PongNetBall.clock_s()

var _router: PongNetRouter = null
var _match: PongMatch = null
var _authority: PongNetAuthority = null
var _reject: Callable = Callable()
# Claims waiting for their bounce to show in our path: [sender, epoch, victim, arrived at].
var _pending: Array[Array] = []
# When (match seconds) this peer first saw each epoch, and the last epoch it saw.
var _epoch_from: Dictionary[int, float] = {}
var _seen_epoch: int = 0


## Follows [param p_match]; sends and takes through [param router]; [param p_reject] as
## [PongNetWeapons] takes it.
func _init(
	router: PongNetRouter, p_match: PongMatch, authority: PongNetAuthority, p_reject: Callable
) -> void:
	_router = router
	_match = p_match
	_authority = authority
	_reject = p_reject
	judge = PongNetHurtJudge.new(_match.court, _authority.owners.size())
	_router.handle(PongNetFloorClaimMessage.SCHEMA_ID, on_claim)
	_router.handle(PongNetFloorHurtMessage.SCHEMA_ID, on_hurt)


## An event of our servo: a floor bounce is recorded (server) and, when we are the
## master, charged (server) or claimed (client); [param before_transfer]: it happened
## before the last transfer reached our servo, in an epoch we may not have mastered.
func on_event(event: PongEvent, before_transfer: bool = false) -> void:
	if event.type != PongServoFacts.PongEventType.FLOOR:
		return
	var territory: int = event.territory
	var on_server: bool = _is_server()
	var ours: bool = (
		_authority.is_master()
		and not before_transfer
		and territory >= 0
		and territory < judge.seats
	)
	if on_server:
		judge.observe_floor(now(), event.position, ours)
	if not ours or _match.rules.is_over():
		return
	if on_server:
		_charge(_authority.epoch, territory)
	else:
		var claim: PongNetFloorClaimMessage = PongNetFloorClaimMessage.new()
		claim.epoch = _authority.epoch
		claim.victim = territory
		_router.send_to(PongNetAuthority.SERVER_ID, claim)
		claimed.emit(claim.epoch, event)


## Each frame on the server: the ball's path, and the claims that were waiting for it.
func observe(snapshot: PongState) -> void:
	if not _is_server():
		return
	var here: float = now()
	for epoch: int in range(_seen_epoch + 1, _authority.epoch + 1):
		_epoch_from[epoch] = here
	_seen_epoch = maxi(_seen_epoch, _authority.epoch)
	var master: bool = _authority.is_master()
	judge.observe(here, snapshot.ball_position, snapshot.ball_velocity, master)
	_settle()


## Server, following a client master: [param states] of its stream were played here at
## [param now_s] ([method PongNetBall.clock_s]); each was its ball that long ago.
func observe_master(states: Array[PongNetBallBuffer.State], now_s: float) -> void:
	if not _is_server():
		return
	var here: float = now()
	for state: PongNetBallBuffer.State in states:
		judge.observe_master(here - state.age_at(now_s), state.position, state.velocity)


## Server: [param sender] claims that a floor bounce at its epoch cost its victim a point.
func on_claim(sender: int, claim: PongNetFloorClaimMessage) -> void:
	if not _is_server():
		return
	var reason: String = PongNetProtocol.check_seat(claim.victim, judge.seats, "victim")
	if reason.is_empty() and (claim.epoch < 1 or claim.epoch > _authority.epoch):
		reason = "epoch %d of %d" % [claim.epoch, _authority.epoch]
	if reason.is_empty() and _authority.master_at(claim.epoch) != sender:
		reason = "peer %d was not the master at epoch %d" % [sender, claim.epoch]
	if reason.is_empty() and _pending.size() >= judge.max_waiting():
		reason = "%d floor claims wait already, more than a ball bounces" % _pending.size()
	if not reason.is_empty():
		_reject.call(sender, PongNetFloorClaimMessage.LABEL, reason)
		return
	_pending.append([sender, claim.epoch, claim.victim, now()])
	_settle()


## A health loss the server charged (only the server sends it: the router).
func on_hurt(sender: int, hurt: PongNetFloorHurtMessage) -> void:
	var reason: String = PongNetProtocol.check_seat(hurt.victim, judge.seats, "victim")
	if reason.is_empty() and hurt.epoch > _authority.epoch:
		reason = "epoch %d of %d" % [hurt.epoch, _authority.epoch]
	if not reason.is_empty():
		_reject.call(sender, PongNetFloorHurtMessage.LABEL, reason)
		return
	_apply(hurt.epoch, hurt.victim)


## Now on [member clock].
func now() -> float:
	return clock.call()


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
		var verdict: Array = judge.judge(now(), arrived, victim, territory, from, to)
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
	var hurt: PongNetFloorHurtMessage = PongNetFloorHurtMessage.new()
	hurt.epoch = epoch
	hurt.victim = victim
	_router.send_all(hurt)
	_apply(epoch, victim)


func _apply(epoch: int, victim: int) -> void:
	_match.rules.hurt(victim, PongRules.CAUSE_FLOOR)
	hurt_applied.emit(epoch, victim)
