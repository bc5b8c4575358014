class_name PongNetSession
extends Node
## The connection: Godot's [ENetMultiplayerPeer] under [SceneMultiplayer], nothing of our
## own below it. It hosts (a player's machine or the dedicated server; the server is always
## peer 1) or joins, checks the protocol version at connect (auth: each side sends its
## [constant PongNetProtocol.VERSION]; a mismatch is refused with a message on both sides)
## and shortens ENet's timeouts; the cap follows each connection's round trip.
## [br]Every message comes and goes through its [member router] as a raw packet. A heartbeat
## ([PongNetHeartbeat], a [PongNetBeatMessage] each way) drops a peer silent for
## [method PongNetProtocol.heartbeat_timeout_s] (1 to 3 s) at once, whatever ENet's
## retransmissions do. The server takes a few unauthenticated connections per address
## ([PongNetHalfOpen]), tells a client it refuses why ([method refuse]), and disconnects a
## peer whose bad messages reach the budget ([method misbehaved], [PongNetBudget]).

## Connected and authenticated (a client: to the server).
signal connected
## The connection could not be made or was refused ([param reason] says why: a client the
## server refuses in its lobby gets the server's reason here, not [signal server_lost]).
signal failed(reason: String)
## A peer passed the version check (on the server: a new client).
signal peer_joined(peer: int)
signal peer_left(peer: int)
## A client lost its server ([member lost_reason] says how).
signal server_lost
## A peer went silent and was dropped after [param silence_s] seconds (the heartbeat).
signal peer_silent(peer: int, silence_s: float)
## [param peer] sent a bad message: a [param what] that [param reason] ([method misbehaved]).
signal bad_message(peer: int, what: String, reason: String)

## Seconds a refused client keeps its connection, so it learns why before it is dropped.
const REFUSAL_GRACE_S: float = 0.5

var is_server: bool = false
## The last refusal or failure, for the UI.
var last_error: String = ""
## The version this peer claims (a test may set another to be refused).
var version: String = PongNetProtocol.VERSION
## How the server was lost (a client): it left, or it went silent.
var lost_reason: String = ""
## Bad messages by peer (see [method misbehaved]).
var budget: PongNetBudget = PongNetBudget.new()
## Every message of this peer comes and goes through it.
var router: PongNetRouter = null

var _peer: ENetMultiplayerPeer = null
var _retune_in: float = 0.0
var _heartbeat: PongNetHeartbeat = PongNetHeartbeat.new()
var _half_open: PongNetHalfOpen = PongNetHalfOpen.new()
# The reason the server sent before it drops us (a client), or "".
var _refusal: String = ""
# Peers to drop at the next frame (see drop_now).
var _drops: Array[int] = []


func _init() -> void:
	router = PongNetRouter.new()
	router.name = "Router"
	add_child(router)
	router.handle(PongNetBeatMessage.SCHEMA_ID, _on_beat)
	router.handle(PongNetStallMessage.SCHEMA_ID, _on_stall)
	router.handle(PongNetRefusalMessage.SCHEMA_ID, _on_refusal)


## Hosts on [param port] (all interfaces unless [param bind_ip]); "" or the error.
func host(port: int, max_clients: int, bind_ip: String = "*") -> String:
	close()
	_reset()
	_peer = ENetMultiplayerPeer.new()
	_peer.set_bind_ip(bind_ip)
	var error: Error = _peer.create_server(port, max_clients)
	if error != OK:
		_peer = null
		return _fail("cannot host on port %d: %s" % [port, error_string(error)])
	is_server = true
	_install()
	return ""


## Joins [param address]:[param port]; "" or the error (then [signal connected] or [signal failed]).
func join(address: String, port: int) -> String:
	close()
	_reset()
	_peer = ENetMultiplayerPeer.new()
	var error: Error = _peer.create_client(address, port)
	if error != OK:
		_peer = null
		return _fail("cannot connect to %s:%d: %s" % [address, port, error_string(error)])
	is_server = false
	PongNetEnet.tune_connect(_peer.get_peer(1))
	_install()
	return ""


## Leaves: the other peers see us go at once (ENet says goodbye).
func close() -> void:
	var api: SceneMultiplayer = _api()
	if _peer != null:
		# Closing reports each peer as gone, synchronously: by then we are closed (nobody
		# answers them on a dead host).
		var closing: ENetMultiplayerPeer = _peer
		_peer = null
		closing.close()
	if api != null:
		api.multiplayer_peer = OfflineMultiplayerPeer.new()
		for pair: Array in _connections(api) + [[api.peer_packet, router.receive]]:
			var sig: Signal = pair[0]
			var handler: Callable = pair[1]
			if sig.is_connected(handler):
				sig.disconnect(handler)
	is_server = false
	_heartbeat.clear()
	_half_open.clear()
	router.forget_peer(0)


func is_open() -> bool:
	return _peer != null


## Round trip to [param peer] (a client knows only the server's), seconds; 0 when unknown.
func round_trip_s(peer: int) -> float:
	if _peer == null or peer == multiplayer.get_unique_id():
		return 0.0
	var packet_peer: ENetPacketPeer = _peer.get_peer(peer)
	if packet_peer == null:
		return 0.0
	return packet_peer.get_statistic(ENetPacketPeer.PEER_ROUND_TRIP_TIME) / 1000.0


## Server: refuses [param peer] (connected, not a player) for [param reason]: the client
## gets the reason, then is dropped [constant REFUSAL_GRACE_S] later.
func refuse(peer: int, reason: String) -> void:
	printerr("PongNet: refused peer %d: %s" % [peer, reason])
	var api: SceneMultiplayer = _api()
	if not is_server or api == null or not api.get_peers().has(peer):
		return
	var refusal: PongNetRefusalMessage = PongNetRefusalMessage.new()
	refusal.reason = reason
	while refusal.reason.to_utf8_buffer().size() > PongNetFacts.NET_MAX_REASON_BYTES:
		refusal.reason = refusal.reason.left(-1)
	router.send_to(peer, refusal)
	get_tree().create_timer(REFUSAL_GRACE_S, true, false, true).timeout.connect(drop_now.bind(peer))


## [param peer] sent a bad message ([param what], [param reason]). The first from a peer is
## logged, the rest counted; a server disconnects the peer when its count reaches the budget.
## Returns whether the peer is being disconnected for it.
func misbehaved(peer: int, what: String, reason: String) -> bool:
	bad_message.emit(peer, what, reason)
	var verdict: PongNetBudget.Verdict = budget.note(peer)
	var drops: bool = verdict == PongNetBudget.Verdict.DISCONNECT and is_server
	var line: String = budget.log_line(verdict, peer, what, reason)
	# A client cannot disconnect the server; it has said so once.
	if not line.is_empty() and (drops or verdict != PongNetBudget.Verdict.DISCONNECT):
		printerr(line)
	if drops:
		drop_now(peer)
	return drops


## Server: drops [param peer] at this node's next frame, without awaiting a goodbye: its
## departure is reported as any other (a match gives its seats to the computer).
func drop_now(peer: int) -> void:
	if is_server and not _drops.has(peer):
		_drops.append(peer)


## Tells the peers this one stalls to load a court (see [method PongNetHeartbeat.settle]).
func announce_stall() -> void:
	_heartbeat.settle()
	if _peer != null and _api() != null:
		_send_watch(PongNetStallMessage.new())
		PongNetEnet.brace(_peer, _api(), is_server)


# Beats when due (our own stalls excused); every second, timeouts from each path's round trip.
func _process(delta: float) -> void:
	if _peer == null:
		return
	_flush_drops()
	_heartbeat.frame(_now_s())
	_beat()
	_retune_in -= delta
	if _retune_in <= 0.0:
		_retune_in = 1.0
		PongNetEnet.retune(_peer, _api(), is_server, _heartbeat.bears_stall)


func _install() -> void:
	var api: SceneMultiplayer = _api()
	api.auth_callback = _on_auth
	api.auth_timeout = PongNetProtocol.AUTH_TIMEOUT_S
	for pair: Array in _connections(api) + [[api.peer_packet, router.receive]]:
		var sig: Signal = pair[0]
		var handler: Callable = pair[1]
		if not sig.is_connected(handler):
			sig.connect(handler)
	api.multiplayer_peer = _peer


func _reset() -> void:
	_drops.clear()
	last_error = ""
	lost_reason = ""
	_refusal = ""
	budget = PongNetBudget.new()
	_heartbeat.clear()
	_half_open.clear()


static func _now_s() -> float:
	return Time.get_ticks_usec() / 1e6


# Sends our beats when due, then drops every peer silent for longer than its path allows.
func _beat() -> void:
	var api: SceneMultiplayer = _api()
	if api == null or _peer == null:
		return
	if _peer.get_connection_status() != MultiplayerPeer.CONNECTION_CONNECTED:
		return
	var now: float = _now_s()
	var peers: PackedInt32Array = api.get_peers()
	if _heartbeat.settling():
		_send_watch(PongNetStallMessage.new())
	elif _heartbeat.due(now):
		_send_watch(PongNetBeatMessage.new())
	var limit_of: Callable = func(peer: int) -> float:
		if _heartbeat.is_stalling(peer):
			return PongNetProtocol.LOAD_STALL_TIMEOUT_S
		var path: ENetPacketPeer = _peer.get_peer(peer) if peers.has(peer) else null
		return PongNetEnet.heartbeat_limit(path)
	for dead: Array in _heartbeat.overdue(now, limit_of):
		var peer: int = dead[0]
		var silence: float = dead[1]
		var limit: float = dead[2]
		printerr(
			"PongNet: peer %d silent for %.2f s (limit %.2f s): dropped" % [peer, silence, limit]
		)
		peer_silent.emit(peer, silence)
		if is_server:
			drop_now(peer)
			_flush_drops()
		else:
			lost_reason = "no word from the server for %.1f s" % silence
			_on_server_disconnected()
			return


# Drops the peers queued by drop_now (PongNetEnet.drop: Godot forgets them at once).
func _flush_drops() -> void:
	var api: SceneMultiplayer = _api()
	if _drops.is_empty() or api == null:
		return
	var dropping: Array[int] = _drops
	_drops = []
	PongNetEnet.drop(api, _peer, dropping)


# To the peers that watch our heartbeat: a server's clients, a client's server.
func _send_watch(message: PongNetMessage) -> void:
	for peer: int in _api().get_peers():
		if is_server or peer == PongNetAuthority.SERVER_ID:
			router.send_to(peer, message)


func _on_beat(peer: int, _message: PongNetBeatMessage) -> void:
	_heartbeat.heard(peer, _now_s())


func _on_stall(peer: int, _message: PongNetStallMessage) -> void:
	_heartbeat.stalls(peer, _now_s())
	PongNetEnet.bear_stall(_peer.get_peer(peer))


# Why the server refuses us, before it drops us (only the server sends it: the router).
func _on_refusal(_sender: int, refusal: PongNetRefusalMessage) -> void:
	_refusal = refusal.reason


func _connections(api: SceneMultiplayer) -> Array[Array]:
	return [
		[api.peer_authenticating, _on_authenticating],
		[api.peer_authentication_failed, _on_authentication_failed],
		[api.peer_connected, _on_peer_connected],
		[api.peer_disconnected, _on_peer_disconnected],
		[api.connected_to_server, _on_connected],
		[api.connection_failed, _on_connection_failed],
		[api.server_disconnected, _on_server_disconnected],
	]


func _exit_tree() -> void:
	close()


func _api() -> SceneMultiplayer:
	return multiplayer as SceneMultiplayer if is_inside_tree() else null


func _on_authenticating(peer: int) -> void:
	# Somebody answered: from here the cap follows the round trip (the short connect cap
	# dropped lossy handshakes, and a server's pending peers kept ENet's 30 s).
	PongNetEnet.tune(_peer.get_peer(peer))
	if is_server:
		var address: String = _peer.get_peer(peer).get_remote_address()
		for oldest: int in _half_open.add(peer, address, _now_s()):
			printerr(
				"PongNet: dropped unauthenticated peer %d of %s (too many)" % [oldest, address]
			)
			drop_now(oldest)
	_api().send_auth(peer, version.to_utf8_buffer())


func _on_auth(peer: int, data: PackedByteArray) -> void:
	var theirs: String = "?"
	if data.size() <= PongNetProtocol.MAX_AUTH_BYTES:
		theirs = data.get_string_from_utf8()
	if theirs == version:
		_api().complete_auth(peer)
		return
	var reason: String = (
		"refused: %s runs protocol '%s', this game runs '%s'"
		% ["a client" if is_server else "the server", theirs, version]
	)
	printerr("PongNet: peer %d %s" % [peer, reason])
	if is_server:
		# Not at once: the client first gets our version (sent when it began to
		# authenticate) and says why on its side too.
		get_tree().create_timer(REFUSAL_GRACE_S, true, false, true).timeout.connect(
			_drop.bind(peer)
		)
	else:
		_fail(reason)
		close()


func _drop(peer: int) -> void:
	var api: SceneMultiplayer = _api()
	if api != null and _peer != null and api.get_authenticating_peers().has(peer):
		api.disconnect_peer(peer)


func _on_authentication_failed(peer: int) -> void:
	_half_open.remove(peer)
	if not is_server:
		_fail("the server refused the connection (version check or timeout)")
	else:
		printerr("PongNet: peer %d failed the version check" % peer)


func _on_peer_connected(peer: int) -> void:
	if is_server:
		PongNetEnet.tune(_peer.get_peer(peer))
		_half_open.remove(peer)
		_heartbeat.watch(peer, _now_s())
	peer_joined.emit(peer)


func _on_peer_disconnected(peer: int) -> void:
	_heartbeat.forget(peer)
	router.forget_peer(peer)
	_half_open.remove(peer)
	peer_left.emit(peer)


func _on_connected() -> void:
	# From the round trip ENet assumes before it has measured one (500 ms): a fixed LAN cap
	# here dropped a live server on a slow lossy path before the first retune.
	PongNetEnet.tune(_peer.get_peer(1))
	_heartbeat.watch(PongNetAuthority.SERVER_ID, _now_s())
	connected.emit()


func _on_connection_failed() -> void:
	_fail(last_error if not last_error.is_empty() else "no answer from the server")
	close()


func _on_server_disconnected() -> void:
	if not _refusal.is_empty():
		_fail("the server refused us: %s" % _refusal)
		close()
		return
	if lost_reason.is_empty():
		# ENet's own timeout, tuned to the path (PongNetEnet.tune), may fire in the same frame
		# as the heartbeat's: after two beats of silence the server was lost, it did not leave.
		var silence: float = _heartbeat.silence_s(PongNetAuthority.SERVER_ID, _now_s())
		var lost: bool = silence >= 2.0 / PongNetProtocol.HEARTBEAT_HZ
		lost_reason = "no word from the server for %.1f s" % silence if lost else "the server left"
	server_lost.emit()
	close()


func _fail(reason: String) -> String:
	last_error = reason
	printerr("PongNet: %s" % reason)
	failed.emit(reason)
	return reason
