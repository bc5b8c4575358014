class_name PongNetSession
extends Node
## The connection: Godot's [ENetMultiplayerPeer] under [SceneMultiplayer], nothing of our
## own below it. It hosts (a player's machine or the dedicated server; the server is always
## peer 1) or joins, checks the protocol version at connect (auth: each side sends its
## [constant PongNetProtocol.VERSION]; a mismatch is refused with a message on both sides)
## and leaves dead peers to the heartbeat.
## [br]Every message comes and goes through its [member router] as a raw packet. A heartbeat
## ([member pulse], a [PongNetBeatMessage] each way) drops a peer silent for
## [method PongNetProtocol.heartbeat_timeout_s] (1 to 3 s), or, when it holds a seat in a
## match, keeps it absent for [constant PongNetProtocol.SEAT_GRACE_S] first. The server
## takes a few unauthenticated connections per address ([PongNetHalfOpen]), watches its
## ENet slots for floods of connection requests ([PongNetFlood]), tells a client it refuses
## why ([method refuse]), and disconnects a peer whose bad messages reach the budget
## ([method misbehaved], [PongNetBudget]).

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
## A join got no answer yet and tries again ([param attempt]: 2, 3...; see
## [constant PongNetProtocol.JOIN_PATIENCE_S]).
signal retrying(attempt: int)
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
## The heartbeat: who is absent, back or lost.
var pulse: PongNetPulse = null

var _peer: ENetMultiplayerPeer = null
var _half_open: PongNetHalfOpen = PongNetHalfOpen.new()
# A server's watch for floods of connection requests (null on a client).
var _flood: PongNetFlood = null
# The reason the server sent before it drops us (a client), or "".
var _refusal: String = ""
# Peers to drop at the next frame (see drop_now).
var _drops: Array[int] = []
# A join under way: [address, port], until connected (empty otherwise); its tries, and until
# when (pulse clock) it tries again.
var _joining: Array = []
var _join_tries: int = 0
var _join_until_s: float = 0.0


func _init() -> void:
	router = PongNetRouter.new()
	router.name = "Router"
	add_child(router)
	pulse = PongNetPulse.new(router)
	pulse.name = "Pulse"
	add_child(pulse)
	pulse.peer_lost.connect(_lose)
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
	_flood = PongNetFlood.new(bind_ip, port, max_clients)
	_install()
	return ""


## Joins [param address]:[param port]; "" or the error (then [signal connected] or [signal failed]).
func join(address: String, port: int) -> String:
	close()
	_reset()
	_join_tries = 1
	_join_until_s = PongNetPulse.now_s() + PongNetProtocol.JOIN_PATIENCE_S
	return _connect(address, port)


# One try of a join.
func _connect(address: String, port: int) -> String:
	_peer = ENetMultiplayerPeer.new()
	var error: Error = _peer.create_client(address, port)
	if error != OK:
		_peer = null
		return _fail("cannot connect to %s:%d: %s" % [address, port, error_string(error)])
	is_server = false
	_joining = [address, port]
	PongNetEnet.tune_connect(_peer.get_peer(1))
	_install()
	return ""


## A client gives its server up: [param reason] is [member lost_reason]; [signal server_lost].
func lose_server(reason: String) -> void:
	lost_reason = reason
	server_lost.emit()
	close()


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
		_wire(api, false)
	is_server = false
	if _flood != null:
		_flood.close()
		_flood = null
	_joining = []
	pulse.heartbeat.clear()
	_half_open.clear()
	router.forget_peer(0)


func is_open() -> bool:
	return _peer != null


## Round trip to [param peer] (a client knows only the server's), seconds; 0 when unknown.
func round_trip_s(peer: int) -> float:
	if _peer == null or peer == multiplayer.get_unique_id():
		return 0.0
	if not is_server and peer != PongNetAuthority.SERVER_ID:
		return 0.0  # Another client, reached only through the server's forwards: no path of ours.
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
	pulse.announce_stall(_peer)


# The heartbeat, then the peers dropped meanwhile.
func _process(_delta: float) -> void:
	if _peer == null:
		return
	_flush_drops()
	pulse.frame(_peer)
	_flush_drops()
	if _flood != null:
		_peer = _flood.frame(_peer, _api())
		if _peer == null:
			_fail("cannot host on port %d again after a flood" % _flood.port)
			close()


func _install() -> void:
	var api: SceneMultiplayer = _api()
	api.auth_callback = _on_auth
	api.auth_timeout = PongNetProtocol.AUTH_TIMEOUT_S
	# Clients reach each other through the router's forwards only (PongNetForward).
	api.server_relay = false
	_wire(api, true)
	api.multiplayer_peer = _peer


func _reset() -> void:
	_drops.clear()
	last_error = ""
	lost_reason = ""
	_refusal = ""
	budget = PongNetBudget.new()
	pulse.heartbeat.clear()
	_half_open.clear()


# [param peer] has been silent for [param silence] seconds (the pulse): a server drops it, a
# client has lost its server.
func _lose(peer: int, silence: float) -> void:
	if is_server:
		drop_now(peer)
	else:
		lost_reason = "no word from the server for %.1f s" % silence
		if silence > PongNetProtocol.SEAT_GRACE_S:
			lost_reason += ": your seat was given up"
		_on_server_disconnected()


# Drops the peers queued by drop_now (PongNetEnet.drop: Godot forgets them at once).
func _flush_drops() -> void:
	var api: SceneMultiplayer = _api()
	if _drops.is_empty() or api == null:
		return
	var dropping: Array[int] = _drops
	_drops = []
	PongNetEnet.drop(api, _peer, dropping)


# Why the server refuses us, before it drops us (only the server sends it: the router).
func _on_refusal(_sender: int, refusal: PongNetRefusalMessage) -> void:
	_refusal = refusal.reason


# Connects (or, [param on] false, disconnects) our handlers to [param api]'s signals.
func _wire(api: SceneMultiplayer, on: bool) -> void:
	var pairs: Array[Array] = [
		[api.peer_authenticating, _on_authenticating],
		[api.peer_authentication_failed, _on_authentication_failed],
		[api.peer_connected, _on_peer_connected],
		[api.peer_disconnected, _on_peer_disconnected],
		[api.connected_to_server, _on_connected],
		[api.connection_failed, _on_connection_failed],
		[api.server_disconnected, _on_server_disconnected],
		[api.peer_packet, router.receive],
	]
	for pair: Array in pairs:
		var sig: Signal = pair[0]
		var handler: Callable = pair[1]
		if on and not sig.is_connected(handler):
			sig.connect(handler)
		elif not on and sig.is_connected(handler):
			sig.disconnect(handler)


func _exit_tree() -> void:
	close()


func _api() -> SceneMultiplayer:
	return multiplayer as SceneMultiplayer if is_inside_tree() else null


func _on_authenticating(peer: int) -> void:
	# Somebody answered: from here the heartbeat decides (the short connect cap dropped
	# lossy handshakes).
	PongNetEnet.tune(_peer.get_peer(peer))
	if is_server:
		var address: String = _peer.get_peer(peer).get_remote_address()
		for oldest: int in _half_open.add(peer, address, PongNetPulse.now_s()):
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
		pulse.heartbeat.watch(peer, PongNetPulse.now_s())
	peer_joined.emit(peer)


func _on_peer_disconnected(peer: int) -> void:
	pulse.heartbeat.forget(peer)
	pulse.legs.forget(peer)
	router.forget_peer(peer)
	_half_open.remove(peer)
	peer_left.emit(peer)


func _on_connected() -> void:
	_joining = []
	PongNetEnet.tune(_peer.get_peer(1))
	pulse.heartbeat.watch(PongNetAuthority.SERVER_ID, PongNetPulse.now_s())
	connected.emit()


func _on_connection_failed() -> void:
	var target: Array = _joining
	close()
	if not target.is_empty() and PongNetPulse.now_s() < _join_until_s:
		_join_tries += 1
		printerr("PongNet: no answer from %s:%d yet: try %d" % [target[0], target[1], _join_tries])
		retrying.emit(_join_tries)
		# After this signal is over: a new peer is not to be installed from inside the old one's.
		_connect.call_deferred(target[0], target[1])
		return
	var tries: String = " (%d tries in %.0f s)" % [_join_tries, PongNetProtocol.JOIN_PATIENCE_S]
	_fail(last_error if not last_error.is_empty() else "no answer from the server" + tries)


func _on_server_disconnected() -> void:
	if not _refusal.is_empty():
		_fail("the server refused us: %s" % _refusal)
		close()
		return
	if lost_reason.is_empty():
		# ENet's own timeout may fire in the same frame as the heartbeat's: after two beats of
		# silence the server was lost, it did not leave.
		var now: float = PongNetPulse.now_s()
		var silence: float = pulse.heartbeat.silence_s(PongNetAuthority.SERVER_ID, now)
		var lost: bool = silence >= 2.0 / PongNetProtocol.HEARTBEAT_HZ
		lost_reason = "no word from the server for %.1f s" % silence if lost else "the server left"
	lose_server(lost_reason)


func _fail(reason: String) -> String:
	last_error = reason
	printerr("PongNet: %s" % reason)
	failed.emit(reason)
	return reason
