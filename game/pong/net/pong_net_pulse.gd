class_name PongNetPulse
extends Node
## The session's heartbeat on the wire: it sends this peer's beats (or, while it loads a
## court, stall notices) to the peers that watch them (a server's clients, a client's
## server), hears theirs, and says who is absent, back or lost. [member heartbeat] keeps the
## times; the session watches and forgets peers as they connect and leave.

## A peer holding a seat ([member keeps_seat]; a client: its server) has been silent past its
## limit for [param silence_s] seconds: absent, its seat kept for
## [constant PongNetProtocol.SEAT_GRACE_S] unless it is heard again.
signal peer_absent(peer: int, silence_s: float)
## An absent peer was heard again after [param silence_s] seconds.
signal peer_back(peer: int, silence_s: float)
## [param peer] is gone after [param silence_s] seconds of silence (past its limit, or absent
## past the grace).
signal peer_lost(peer: int, silence_s: float)

## Whether a silent peer keeps its seat (Callable(peer) -> bool; a client: its server): set
## by the match; unset, a silent peer is lost at its limit.
var keeps_seat: Callable = Callable()
var heartbeat: PongNetHeartbeat = PongNetHeartbeat.new()
## Each direction's delay to the peers whose beats this one hears.
var legs: PongNetLegs = PongNetLegs.new()

var _router: PongNetRouter = null
var _enet: ENetMultiplayerPeer = null


func _init(router: PongNetRouter) -> void:
	_router = router
	router.handle(PongNetBeatMessage.SCHEMA_ID, _on_beat)
	router.handle(PongNetStallMessage.SCHEMA_ID, _on_stall)


## One frame of the session over [param enet]: after a stall of our own what came meanwhile
## read first, beats when due, then the verdicts (at most one lost peer on a client, whose
## session then closes).
func frame(enet: ENetMultiplayerPeer) -> void:
	_enet = enet
	var now: float = now_s()
	if heartbeat.frame(now) and multiplayer.multiplayer_peer == enet:
		multiplayer.poll()
		now = now_s()
	if enet.get_connection_status() != MultiplayerPeer.CONNECTION_CONNECTED:
		return
	if heartbeat.settling():
		_send_watch(PongNetStallMessage.new())
	elif heartbeat.due(now):
		_send_beats()
	for back: Array in heartbeat.returned():
		printerr("PongNet: peer %d back after %.2f s of silence" % back)
		peer_back.emit(back[0], back[1])
	var overdue: Array[Array] = heartbeat.overdue(now, _limit_of, keeps_seat)
	for dead: Array in overdue + heartbeat.given_up(now, PongNetProtocol.SEAT_GRACE_S):
		var peer: int = dead[0]
		var silence: float = dead[1]
		var kept: bool = heartbeat.is_absent(peer)
		var grace: String = "its seat kept for %.0f s" % PongNetProtocol.SEAT_GRACE_S
		var fate: String = grace if kept else "its seat given up" if dead.size() < 3 else "lost"
		printerr("PongNet: peer %d silent for %.2f s: %s" % [peer, silence, fate])
		if kept:
			peer_absent.emit(peer, silence)
		else:
			peer_lost.emit(peer, silence)
			if not _is_server():
				return


## Tells the peers this one stalls to load a court (see [method PongNetHeartbeat.settle]);
## what is queued leaves now rather than after the stall.
func announce_stall(enet: ENetMultiplayerPeer) -> void:
	heartbeat.settle()
	if enet != null and is_inside_tree():
		_send_watch(PongNetStallMessage.new())
		PongNetEnet.brace(enet)


## Seconds of the one monotonic clock the heartbeat counts in.
static func now_s() -> float:
	return Time.get_ticks_usec() / 1e6


func _is_server() -> bool:
	return multiplayer.get_unique_id() == PongNetAuthority.SERVER_ID


# The silence after which [param peer] is overdue, seconds.
func _limit_of(peer: int) -> float:
	if heartbeat.is_stalling(peer):
		return PongNetProtocol.LOAD_STALL_TIMEOUT_S
	var known: bool = _enet != null and multiplayer.get_peers().has(peer)
	return PongNetEnet.heartbeat_limit(_enet.get_peer(peer) if known else null)


# To the peers that watch our heartbeat: a server's clients, a client's server.
func _send_watch(message: PongNetMessage) -> void:
	for peer: int in _watching():
		_router.send_to(peer, message)


func _watching() -> Array[int]:
	var peers: Array[int] = []
	for peer: int in multiplayer.get_peers():
		if _is_server() or peer == PongNetAuthority.SERVER_ID:
			peers.append(peer)
	return peers


# A beat to each watching peer, with what we measured of its beats.
func _send_beats() -> void:
	for peer: int in _watching():
		var beat: PongNetBeatMessage = PongNetBeatMessage.new()
		beat.wall_s = PongNetLegs.wall_s()
		var heard_ms: float = legs.inbound_ms(peer)
		beat.heard = is_finite(heard_ms)
		if beat.heard:
			var most: float = PongNetFacts.NET_MAX_LEG_MS
			beat.heard_ms = clampf(heard_ms, -most, most)
		_router.send_to(peer, beat)


func _on_beat(peer: int, message: PongNetBeatMessage) -> void:
	heartbeat.heard(peer, now_s())
	var heard_ms: float = message.heard_ms if message.heard else NAN
	legs.heard(peer, PongNetLegs.wall_s(), message.wall_s, heard_ms)


func _on_stall(peer: int, _message: PongNetStallMessage) -> void:
	heartbeat.stalls(peer, now_s())
