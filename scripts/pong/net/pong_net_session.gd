class_name PongNetSession
extends Node
## The connection: Godot's [ENetMultiplayerPeer] under [SceneMultiplayer], nothing of our
## own below it. It hosts (a player's machine or the dedicated server; the server is always
## peer 1) or joins, checks the protocol version at connect (auth: each side sends its
## [constant PongNetProtocol.VERSION]; a mismatch is refused with a message on both sides)
## and shortens ENet's timeouts so a dead peer is noticed in about a second on a LAN
## (FACTS §1.7), not ten; the cap follows each connection's round trip.

## Connected and authenticated (a client: to the server).
signal connected
## The connection could not be made or was refused ([param reason] says why).
signal failed(reason: String)
## A peer passed the version check (on the server: a new client).
signal peer_joined(peer: int)
signal peer_left(peer: int)
## A client lost its server.
signal server_lost

## Seconds a refused client keeps its connection, so it learns why before it is dropped.
const REFUSAL_GRACE_S: float = 0.5

var is_server: bool = false
## The last refusal or failure, for the UI.
var last_error: String = ""
## Seconds from a peer's loss to its notice are the ENet timeouts' business; this is when
## the notice came (Time.get_ticks_msec) by peer, for the report.
var left_at_ms: Dictionary[int, int] = {}
## The version this peer claims (a test may set another to be refused).
var version: String = PongNetProtocol.VERSION

var _peer: ENetMultiplayerPeer = null
var _retune_in: float = 0.0


## Hosts on [param port] (all interfaces unless [param bind_ip]); "" or the error.
func host(port: int, max_clients: int, bind_ip: String = "*") -> String:
	close()
	_peer = ENetMultiplayerPeer.new()
	_peer.set_bind_ip(bind_ip)
	var error: Error = _peer.create_server(port, max_clients)
	if error != OK:
		_peer = null
		return _fail("cannot host on port %d: %s" % [port, error_string(error)])
	is_server = true
	_install()
	return ""


## Joins the server at [param address]:[param port]; "" or the error (the outcome comes as
## [signal connected] or [signal failed]).
func join(address: String, port: int) -> String:
	close()
	_peer = ENetMultiplayerPeer.new()
	var error: Error = _peer.create_client(address, port)
	if error != OK:
		_peer = null
		return _fail("cannot connect to %s:%d: %s" % [address, port, error_string(error)])
	is_server = false
	_peer.get_peer(1).set_timeout(
		PongNetProtocol.TIMEOUT_LIMIT,
		PongNetProtocol.CONNECT_TIMEOUT_MIN_MS,
		PongNetProtocol.CONNECT_TIMEOUT_MAX_MS
	)
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
		for pair: Array in _connections(api):
			var sig: Signal = pair[0]
			var handler: Callable = pair[1]
			if sig.is_connected(handler):
				sig.disconnect(handler)
	is_server = false


func is_open() -> bool:
	return _peer != null


## Round trip to [param peer] (a server: to each client; a client: only to the server,
## id 1), seconds; 0 when unknown or ourselves.
func round_trip_s(peer: int) -> float:
	if _peer == null or peer == multiplayer.get_unique_id():
		return 0.0
	var packet_peer: ENetPacketPeer = _peer.get_peer(peer)
	if packet_peer == null:
		return 0.0
	return packet_peer.get_statistic(ENetPacketPeer.PEER_ROUND_TRIP_TIME) / 1000.0


func _exit_tree() -> void:
	close()


# Every second: the timeouts follow each connection's round trip.
func _process(delta: float) -> void:
	_retune_in -= delta
	if _peer == null or _retune_in > 0.0:
		return
	_retune_in = 1.0
	var ids: Array[int] = []
	if is_server:
		ids.assign(multiplayer.get_peers())
	elif _peer.get_connection_status() == MultiplayerPeer.CONNECTION_CONNECTED:
		ids.append(1)
	for id: int in ids:
		_tune(id)


func _tune(id: int) -> void:
	var packet_peer: ENetPacketPeer = _peer.get_peer(id)
	if packet_peer == null:
		return
	var rtt: float = packet_peer.get_statistic(ENetPacketPeer.PEER_ROUND_TRIP_TIME)
	var variance: float = packet_peer.get_statistic(ENetPacketPeer.PEER_ROUND_TRIP_TIME_VARIANCE)
	packet_peer.set_timeout(
		PongNetProtocol.TIMEOUT_LIMIT,
		PongNetProtocol.TIMEOUT_MIN_MS,
		PongNetProtocol.timeout_max_ms(rtt, variance)
	)
	packet_peer.throttle_configure(
		PongNetProtocol.THROTTLE_INTERVAL_MS,
		PongNetProtocol.THROTTLE_ACCELERATION,
		PongNetProtocol.THROTTLE_DECELERATION
	)


func _install() -> void:
	var api: SceneMultiplayer = _api()
	api.auth_callback = _on_auth
	api.auth_timeout = PongNetProtocol.AUTH_TIMEOUT_S
	for pair: Array in _connections(api):
		var sig: Signal = pair[0]
		var handler: Callable = pair[1]
		if not sig.is_connected(handler):
			sig.connect(handler)
	api.multiplayer_peer = _peer


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


func _api() -> SceneMultiplayer:
	return multiplayer as SceneMultiplayer if is_inside_tree() else null


func _on_authenticating(peer: int) -> void:
	# Somebody answered: from here the cap follows the round trip (the short connect cap
	# dropped lossy handshakes, and a server's pending peers kept ENet's 30 s).
	_tune(peer)
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
	if not is_server:
		_fail("the server refused the connection (version check or timeout)")
	else:
		printerr("PongNet: peer %d failed the version check" % peer)


func _on_peer_connected(peer: int) -> void:
	if is_server:
		_tune(peer)
	peer_joined.emit(peer)


func _on_peer_disconnected(peer: int) -> void:
	left_at_ms[peer] = Time.get_ticks_msec()
	peer_left.emit(peer)


func _on_connected() -> void:
	# From the round trip ENet assumes before it has measured one (500 ms): a fixed LAN cap
	# here dropped a live server on a slow lossy path before the first retune.
	_tune(1)
	connected.emit()


func _on_connection_failed() -> void:
	_fail(last_error if not last_error.is_empty() else "no answer from the server")
	close()


func _on_server_disconnected() -> void:
	server_lost.emit()
	close()


func _fail(reason: String) -> String:
	last_error = reason
	printerr("PongNet: %s" % reason)
	failed.emit(reason)
	return reason
