class_name PongNetAuthority
extends RefCounted
## Who simulates the ball ("the master"), agreed by every peer without wall clocks.
##
## The master of the ball is the owner of the territory it is in (the paper's private
## haptic space). Mastership changes only through numbered transfers (serve, hand-off,
## takeover) that the server alone issues, each with the next [member epoch], reliably and
## in order to every peer: the server is the sequencer, so all peers apply the same
## transfers in the same order. A master whose ball crosses into another territory asks
## the server for the hand-off and stops being master at once; the new owner becomes master
## when the transfer reaches it. Between the two there is no master (the ball flies on in
## every peer's servo), never two. A request the server cannot honour (a newer transfer
## was issued meanwhile, or the sender is not the master) is refused; the newer transfer,
## already on its way to the sender, settles it.
##
## Stream messages carry (epoch, seq): a state is taken only from the current epoch's
## master and only when newer than the last one taken.

## The server's peer id (Godot's is always 1).
const SERVER_ID: int = 1

## Transfers applied so far (every peer's list must be the same).
var epoch: int = 0
## The peer simulating the ball, 0 when none (before the first serve, during a hand-off).
var master_peer: int = 0
## The territory the current transfer put the ball in.
var territory: int = 0
## The peer owning each seat's territory (a player's peer, or the server for a computer).
var owners: PackedInt64Array = PackedInt64Array()
## This peer's id.
var my_id: int = 0
## Every applied transfer in order: {epoch, kind, territory, master}.
var history: Array[Dictionary] = []
## Refused messages by reason (for the report and the tests).
var refusals: Dictionary[String, int] = {}
## Server: the seats the computer plays for an absent player, seat -> that player's peer.
var kept: Dictionary[int, int] = {}
## Client: the seats the server drives now, each with the player it took the seat from, as
## the owners messages told (seat -> peer).
var taken_from: Dictionary[int, int] = {}

var _last_seq: int = -1
var _relinquished: bool = false


func _init(p_my_id: int, p_owners: PackedInt64Array) -> void:
	my_id = p_my_id
	owners = p_owners


## The peer owning [param p_territory] (0 when out of range).
func owner_of(p_territory: int) -> int:
	if p_territory < 0 or p_territory >= owners.size():
		return 0
	return owners[p_territory]


## Whether this peer simulates the ball for everyone now.
func is_master() -> bool:
	return master_peer == my_id and my_id != 0 and not _relinquished


## The master's ball crossed into [param new_territory]: it stops being master and returns
## the request to send the server {epoch, territory}; empty when it was not master.
func relinquish(new_territory: int) -> Dictionary:
	if not is_master():
		return {}
	_relinquished = true
	return {"epoch": epoch, "territory": new_territory}


## Server side: why the hand-off request of [param sender] (made at [param seen_epoch]
## toward [param new_territory]) is refused, or "" when it is to be issued.
func check_request(sender: int, seen_epoch: int, new_territory: int) -> String:
	if sender != master_peer:
		return _refuse("hand-off request from peer %d, not the master %d" % [sender, master_peer])
	if seen_epoch != epoch:
		return _refuse("stale hand-off request (epoch %d, now %d)" % [seen_epoch, epoch])
	if new_territory < 0 or new_territory >= owners.size():
		return _refuse("hand-off request to territory %d of %d" % [new_territory, owners.size()])
	return ""


## Server side: the next transfer of [param kind] putting the ball in [param p_territory];
## its master the territory's owner, or [param master] when given.
func next_transfer(kind: int, p_territory: int, master: int = -1) -> Dictionary:
	return {
		"epoch": epoch + 1,
		"kind": kind,
		"territory": p_territory,
		"master": master if master > 0 else owner_of(p_territory),
	}


## Applies a transfer from [param sender]; "" when applied, else why it was refused.
func apply_transfer(sender: int, transfer: Dictionary) -> String:
	if sender != SERVER_ID:
		return _refuse("transfer from peer %d, only the server issues them" % sender)
	var new_epoch: int = transfer.get("epoch", -1)
	if new_epoch <= epoch:
		return _refuse("stale transfer (epoch %d, now %d)" % [new_epoch, epoch])
	epoch = new_epoch
	territory = transfer.get("territory", 0)
	master_peer = transfer.get("master", 0)
	_relinquished = false
	_last_seq = -1
	history.append(transfer.duplicate())
	return ""


## Whether a stream state (epoch, seq) from [param sender] is to be taken; "" when yes.
func accept_state(sender: int, state_epoch: int, seq: int) -> String:
	if state_epoch != epoch:
		return _refuse("state of epoch %d, now %d" % [state_epoch, epoch], "state epoch")
	if sender != master_peer:
		return _refuse("state from peer %d, not the master %d" % [sender, master_peer])
	if seq <= _last_seq:
		return _refuse("state seq %d not after %d" % [seq, _last_seq], "state order")
	_last_seq = seq
	return ""


## The master that transfer [param at_epoch] installed (0 before the first or unknown).
func master_at(at_epoch: int) -> int:
	for transfer: Dictionary in history:
		if transfer.get("epoch", -1) == at_epoch:
			return transfer.get("master", 0)
	return 0


## The territory transfer [param at_epoch] put the ball in (-1 before the first or unknown).
func territory_at(at_epoch: int) -> int:
	for transfer: Dictionary in history:
		if transfer.get("epoch", -1) == at_epoch:
			return transfer.get("territory", -1)
	return -1


## The peer left: its seats go to the server (a computer player), and the seats kept for it
## are given up. Returns the seats it held.
func release_peer(peer: int) -> PackedInt32Array:
	var freed: PackedInt32Array = PackedInt32Array()
	for seat: int in owners.size():
		if owners[seat] == peer:
			owners[seat] = SERVER_ID
			freed.append(seat)
	for seat: int in kept.keys():
		if kept[seat] == peer:
			kept.erase(seat)
	return freed


## Server: the peer is absent: the server plays its seats, kept for it. Returns the seats.
func stand_in(peer: int) -> PackedInt32Array:
	var freed: PackedInt32Array = release_peer(peer)
	for seat: int in freed:
		kept[seat] = peer
	return freed


## Server: the seats kept for [param old] are kept for [param new_peer] (the same player,
## rejoined under a new connection).
func rekey_kept(old: int, new_peer: int) -> void:
	for seat: int in kept.keys():
		if kept[seat] == old:
			kept[seat] = new_peer


## Client: who drives each seat now (the server's owners message). Returns the seats given
## back to a player the server had taken them from.
func set_owners(p_owners: PackedInt64Array) -> PackedInt32Array:
	var back: PackedInt32Array = PackedInt32Array()
	for seat: int in p_owners.size():
		if p_owners[seat] == SERVER_ID:
			if owners[seat] != SERVER_ID:
				taken_from[seat] = owners[seat]
		elif taken_from.has(seat):
			taken_from.erase(seat)
			back.append(seat)
	owners = p_owners
	return back


## Server: the absent peer is back: the seats kept for it are its own again. Returns them.
func give_back(peer: int) -> PackedInt32Array:
	var back: PackedInt32Array = PackedInt32Array()
	for seat: int in kept.keys():
		if kept[seat] == peer:
			kept.erase(seat)
			owners[seat] = peer
			back.append(seat)
	return back


## Counts a refusal under [param key] (default: the reason's text up to a digit) and
## returns [param reason].
func _refuse(reason: String, key: String = "") -> String:
	var bucket: String = key
	if bucket.is_empty():
		var regex: RegEx = RegEx.create_from_string("^[^0-9(]*")
		bucket = regex.search(reason).get_string().strip_edges()
	refusals[bucket] = refusals.get(bucket, 0) + 1
	return reason
