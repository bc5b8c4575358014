class_name PongNetWire
extends Node
## The RPC surface of a networked match: the same methods at the same path on every peer
## (Godot checks that). Arguments arrive as [Variant]: the engine does not check them, the
## handlers of [PongNetPlay] do, so a malformed call is dropped with our log line instead
## of an engine error. Each stub passes the sender's id on.

## The connection (round trips for the age of messages).
var session: PongNetSession = null
## The match's bullets and mines while a match runs (its messages go there).
var weapons: PongNetWeapons = null
## The match's paddle poses while a match runs (their messages go there).
var poses: PongNetPoses = null


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


# Unreliable, not unreliable_ordered: ENet would drop every state that arrives after a newer
# one before this handler sees it; the follower's buffer orders them (PongNetBallBuffer).
@rpc("any_peer", "call_remote", "unreliable", PongNetProtocol.CHANNEL_BALL)
func _ball(
	epoch: Variant,
	seq: Variant,
	time_s: Variant,
	position: Variant,
	velocity: Variant,
	spin: Variant,
	leg_ms: Variant
) -> void:
	_on_ball(
		multiplayer.get_remote_sender_id(), epoch, seq, time_s, position, velocity, spin, leg_ms
	)


@rpc("any_peer", "call_remote", "unreliable_ordered", PongNetProtocol.CHANNEL_POSE)
func _pose(
	seat: Variant,
	avatar: Variant,
	offset: Variant,
	velocity: Variant,
	normal: Variant,
	flags: Variant,
	time_s: Variant,
	leg_ms: Variant
) -> void:
	if poses != null:
		poses.on_pose(
			multiplayer.get_remote_sender_id(),
			seat,
			avatar,
			offset,
			velocity,
			normal,
			flags,
			time_s,
			leg_ms
		)


@rpc("any_peer", "call_remote", "reliable", PongNetProtocol.CHANNEL_RELIABLE)
func _request(
	epoch: Variant, territory: Variant, position: Variant, velocity: Variant, spin: Variant
) -> void:
	_on_request(multiplayer.get_remote_sender_id(), epoch, territory, position, velocity, spin)


@rpc("any_peer", "call_remote", "reliable", PongNetProtocol.CHANNEL_RELIABLE)
func _transfer(
	epoch: Variant,
	kind: Variant,
	territory: Variant,
	master: Variant,
	position: Variant,
	velocity: Variant,
	spin: Variant,
	age_ms: Variant
) -> void:
	_on_transfer(
		multiplayer.get_remote_sender_id(),
		epoch,
		kind,
		territory,
		master,
		position,
		velocity,
		spin,
		age_ms
	)


@rpc("any_peer", "call_remote", "reliable", PongNetProtocol.CHANNEL_RELIABLE)
func _hurt(epoch: Variant, player: Variant, cause: Variant) -> void:
	_on_hurt(multiplayer.get_remote_sender_id(), epoch, player, cause)


@rpc("any_peer", "call_remote", "reliable", PongNetProtocol.CHANNEL_RELIABLE)
func _owners(owners: Variant) -> void:
	_on_owners(multiplayer.get_remote_sender_id(), owners)


@rpc("any_peer", "call_remote", "reliable", PongNetProtocol.CHANNEL_RELIABLE)
func _bullet(
	seat: Variant, id: Variant, origin: Variant, direction: Variant, time_s: Variant
) -> void:
	if weapons != null:
		weapons.on_bullet(multiplayer.get_remote_sender_id(), seat, id, origin, direction, time_s)


@rpc("any_peer", "call_remote", "reliable", PongNetProtocol.CHANNEL_RELIABLE)
func _mine(seat: Variant, id: Variant, position: Variant, kind: Variant) -> void:
	if weapons != null:
		weapons.on_mine(multiplayer.get_remote_sender_id(), seat, id, position, kind)


@rpc("any_peer", "call_remote", "reliable", PongNetProtocol.CHANNEL_RELIABLE)
func _weapon_hurt(victim: Variant, cause: Variant, seat: Variant, id: Variant) -> void:
	if weapons != null:
		weapons.on_hurt(multiplayer.get_remote_sender_id(), victim, cause, seat, id)


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


func _on_hurt(_sender: int, _epoch: Variant, _player: Variant, _cause: Variant) -> void:
	pass


func _on_owners(_sender: int, _owner_list: Variant) -> void:
	pass
