class_name PongNetSeats
extends RefCounted
## Who plays each seat of a running match: the owners every peer applies
## ([PongNetOwnersMessage], sent by the server alone), and on the server the computer standing
## in for a player who left or is silent. A silent player's seats are kept for it
## ([member PongNetAuthority.kept]) and given back when it is heard again.

## The owners changed (a peer left, went silent, or came back).
signal changed
## Server: the computer took the [param seats] of [param peer] (it left or went silent).
signal taken_over(peer: int, seats: PackedInt32Array)
## Server: the seats kept for the absent [param peer] are its own again.
signal given_back(peer: int, seats: PackedInt32Array)

var _router: PongNetRouter = null
var _match: PongMatch = null
var _authority: PongNetAuthority = null
var _reject: Callable = Callable()
var _take_ball: Callable = Callable()
# When each player that was absent came back (monotonic seconds).
var _back_at: Dictionary[int, float] = {}


## Follows a match through [param router]: [param take_ball] (Callable()) has the server take
## the ball over from its own servo; [param reject] (Callable(sender, what, reason)) counts a
## bad message.
func begin(
	router: PongNetRouter,
	p_match: PongMatch,
	authority: PongNetAuthority,
	take_ball: Callable,
	reject: Callable
) -> void:
	_router = router
	_match = p_match
	_authority = authority
	_take_ball = take_ball
	_reject = reject
	_router.handle(PongNetOwnersMessage.SCHEMA_ID, _on_owners)


## Server: [param peer] left. Its seats go to the computer (driven here), and a ball it was
## master of, or one whose hand-off is pending while the server owns the territory, is taken
## over at once from the server's own ball, so the ball is never left without a master.
func take_over(peer: int) -> void:
	var was_master: bool = _authority.master_peer == peer
	_reseat(peer, _authority.release_peer(peer), was_master)


## Server: [param peer] is absent (silent, its seats kept): the computer stands in for it as
## for a player who left (the rally goes on) until [method give_back].
func stand_in(peer: int) -> void:
	var was_master: bool = _authority.master_peer == peer
	_reseat(peer, _authority.stand_in(peer), was_master)


## Server: the absent [param peer] is heard again: its seats are its own again, and so is the
## ball when it is in one of them.
func give_back(peer: int) -> void:
	var back: PackedInt32Array = _authority.give_back(peer)
	if back.is_empty():
		return
	_back_at[peer] = PongNetPulse.now_s()
	given_back.emit(peer, back)
	_send_owners()
	if _authority.is_master() and back.has(_match.snapshot.territory):
		_take_ball.call()


## Whether what [param peer] sent may be from a time it was cut off: its seat is kept for it
## (on the server), or was taken from it (a client, whose word that the seat is back may
## still be on its way: a pose travels apart from the owners message and can overtake it), or
## it came back within [constant PongNetProtocol.RETURN_SETTLE_S].
func cut_off_lately(peer: int) -> bool:
	if (
		_authority != null
		and (_authority.kept.values().has(peer) or _authority.taken_from.values().has(peer))
	):
		return true
	var since: float = PongNetPulse.now_s() - _back_at.get(peer, -INF)
	return since < PongNetProtocol.RETURN_SETTLE_S


# The seats [param freed] of [param peer] went to the computer: everyone learns it, and the
# server takes the ball over when it has no master to go on with.
func _reseat(peer: int, freed: PackedInt32Array, was_master: bool) -> void:
	if freed.is_empty() and not was_master:
		return
	taken_over.emit(peer, freed)
	_send_owners()
	var pending: bool = _authority.master_peer == 0 or not _authority.is_master()
	var ours: bool = _authority.owner_of(_authority.territory) == PongNetAuthority.SERVER_ID
	if was_master or (pending and ours):
		_take_ball.call()


func _send_owners() -> void:
	var owners: PongNetOwnersMessage = PongNetOwnersMessage.new()
	owners.owners = _authority.owners
	_router.send_all(owners)
	changed.emit()


func _on_owners(sender: int, owners: PongNetOwnersMessage) -> void:
	if owners.owners.size() != _authority.owners.size():
		var seats: Array[int] = [owners.owners.size(), _authority.owners.size()]
		_reject.call(sender, PongNetOwnersMessage.LABEL, "%d seats, the match has %d" % seats)
		return
	for seat: int in _authority.set_owners(owners.owners):
		_back_at[_authority.owners[seat]] = PongNetPulse.now_s()
	changed.emit()
