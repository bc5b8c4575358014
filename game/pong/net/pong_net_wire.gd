class_name PongNetWire
extends Node
## The RPC surface of a networked match: the same methods at the same path on every peer
## (Godot checks that). Arguments arrive as [Variant]s in a list: the engine checks neither
## their types nor their count, the stubs and the handlers of [PongNetPlay] do, so a
## malformed call is one of the sender's bad messages ([method PongNetSession.misbehaved])
## instead of an engine error. Each stub passes the sender's id on.

## The connection (round trips for the age of messages).
var session: PongNetSession = null
## The match's bullets and mines while a match runs (its messages go there).
var weapons: PongNetWeapons = null
## The match's paddle poses while a match runs (their messages go there).
var poses: PongNetPoses = null
## The match's floor hurts while a match runs (claims and charges go there).
var floor_hurts: PongNetFloorHurts = null


## Sends [param method] with [param args] to every other peer.
func send_all(method: StringName, args: Array) -> void:
	if multiplayer.has_multiplayer_peer() and session.is_open():
		callv(&"rpc", [method] + args)


## Sends [param method] with [param args] to [param peer] while it is connected (a server
## that just left is no longer one of [method MultiplayerAPI.get_peers]: the engine would
## log an error).
func send_to(peer: int, method: StringName, args: Array) -> void:
	if multiplayer.has_multiplayer_peer() and session.is_open():
		if multiplayer.get_peers().has(peer):
			callv(&"rpc_id", [peer, method] + args)


# Every stub takes its arguments as a list and checks their count: the engine fails a call
# with a wrong count with an error line per message, which a peer could flood the log with;
# here it is one of the peer's bad messages (PongNetSession.misbehaved). The ball's channel
# is unreliable, not unreliable_ordered: ENet would drop every state that arrives after a
# newer one before the handler sees it; the follower's buffer orders them (PongNetBallBuffer).
@rpc("any_peer", "call_remote", "unreliable", PongNetProtocol.CHANNEL_BALL)
func _ball(...args: Array) -> void:
	var state: Array = _args(args, 7, "ball state")
	if not state.is_empty():
		callv(&"_on_ball", [multiplayer.get_remote_sender_id()] + state)


@rpc("any_peer", "call_remote", "unreliable_ordered", PongNetProtocol.CHANNEL_POSE)
func _pose(...args: Array) -> void:
	var pose: Array = _args(args, 8, "pose")
	if poses != null and not pose.is_empty():
		poses.callv(&"on_pose", [multiplayer.get_remote_sender_id()] + pose)


@rpc("any_peer", "call_remote", "reliable", PongNetProtocol.CHANNEL_RELIABLE)
func _request(...args: Array) -> void:
	var request: Array = _args(args, 5, "hand-off request")
	if not request.is_empty():
		callv(&"_on_request", [multiplayer.get_remote_sender_id()] + request)


@rpc("any_peer", "call_remote", "reliable", PongNetProtocol.CHANNEL_RELIABLE)
func _transfer(...args: Array) -> void:
	var transfer: Array = _args(args, 8, "transfer")
	if not transfer.is_empty():
		callv(&"_on_transfer", [multiplayer.get_remote_sender_id()] + transfer)


## A floor bounce's health loss, charged by the server: epoch, victim, cause.
@rpc("any_peer", "call_remote", "reliable", PongNetProtocol.CHANNEL_RELIABLE)
func _hurt(...args: Array) -> void:
	var hurt: Array = _args(args, 3, "hurt")
	if floor_hurts != null and not hurt.is_empty():
		floor_hurts.callv(&"on_hurt", [multiplayer.get_remote_sender_id()] + hurt)


## A master's claim to the server that a floor bounce cost a seat: epoch, victim.
@rpc("any_peer", "call_remote", "reliable", PongNetProtocol.CHANNEL_RELIABLE)
func _claim(...args: Array) -> void:
	var claim: Array = _args(args, 2, "floor claim")
	if floor_hurts != null and not claim.is_empty():
		floor_hurts.callv(&"on_claim", [multiplayer.get_remote_sender_id()] + claim)


@rpc("any_peer", "call_remote", "reliable", PongNetProtocol.CHANNEL_RELIABLE)
func _owners(...args: Array) -> void:
	var owners: Array = _args(args, 1, "owners")
	if not owners.is_empty():
		_on_owners(multiplayer.get_remote_sender_id(), owners[0])


@rpc("any_peer", "call_remote", "reliable", PongNetProtocol.CHANNEL_RELIABLE)
func _bullet(...args: Array) -> void:
	var bullet: Array = _args(args, 5, "bullet")
	if weapons != null and not bullet.is_empty():
		weapons.callv(&"on_bullet", [multiplayer.get_remote_sender_id()] + bullet)


@rpc("any_peer", "call_remote", "reliable", PongNetProtocol.CHANNEL_RELIABLE)
func _mine(...args: Array) -> void:
	var mine: Array = _args(args, 4, "mine")
	if weapons != null and not mine.is_empty():
		weapons.callv(&"on_mine", [multiplayer.get_remote_sender_id()] + mine)


@rpc("any_peer", "call_remote", "reliable", PongNetProtocol.CHANNEL_RELIABLE)
func _weapon_hurt(...args: Array) -> void:
	var hurt: Array = _args(args, 4, "weapon hurt")
	if weapons != null and not hurt.is_empty():
		weapons.callv(&"on_hurt", [multiplayer.get_remote_sender_id()] + hurt)


# [param args] when they are [param count], else [] (the sender's bad message, counted).
func _args(args: Array, count: int, what: String) -> Array:
	var reason: String = PongNetProtocol.check_arity(args, count)
	if reason.is_empty():
		return args
	_reject(multiplayer.get_remote_sender_id(), what, reason)
	return []


# --- handlers, overridden by PongNetPlay ---


func _on_ball(
	_sender: int,
	_epoch: Variant,
	_seq: Variant,
	_time_s: Variant,
	_position: Variant,
	_velocity: Variant,
	_spin: Variant,
	_leg_ms: Variant
) -> void:
	pass


func _on_request(
	_sender: int,
	_epoch: Variant,
	_territory: Variant,
	_position: Variant,
	_velocity: Variant,
	_spin: Variant
) -> void:
	pass


func _on_transfer(
	_sender: int,
	_epoch: Variant,
	_kind: Variant,
	_territory: Variant,
	_master: Variant,
	_position: Variant,
	_velocity: Variant,
	_spin: Variant,
	_age_ms: Variant
) -> void:
	pass


func _on_owners(_sender: int, _owner_list: Variant) -> void:
	pass


## A bad message from [param sender]: dropped, and counted against it.
func _reject(sender: int, what: String, reason: String) -> void:
	if session != null:
		session.misbehaved(sender, what, reason)
