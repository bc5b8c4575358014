class_name PongNetEnet
extends RefCounted
## What [PongNetSession] does to Godot's ENet peers: their timeouts and throttle, the
## heartbeat's limits, and dropping a peer at once.


## Sets [param packet_peer]'s timeouts from its measured round trip (see
## [constant PongNetProtocol.TIMEOUT_RTOS]) and keeps its throttle open.
static func tune(packet_peer: ENetPacketPeer) -> void:
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


## Sets the timeouts of [param packet_peer], a server being connected to (see [constant
## PongNetProtocol.CONNECT_TIMEOUT_MAX_MS]).
static func tune_connect(packet_peer: ENetPacketPeer) -> void:
	packet_peer.set_timeout(
		PongNetProtocol.TIMEOUT_LIMIT,
		PongNetProtocol.CONNECT_TIMEOUT_MIN_MS,
		PongNetProtocol.CONNECT_TIMEOUT_MAX_MS
	)


## Gives [param packet_peer] a load stall's patience ([constant
## PongNetProtocol.LOAD_STALL_TIMEOUT_S]). ENet drops a peer whose reliable packets stay
## unacknowledged past its timeout, and a stalled frame answers nothing on either side: at
## the round trip's timeout (under 1 s on a LAN) a player's slow court load cost the seat.
static func bear_stall(packet_peer: ENetPacketPeer) -> void:
	if packet_peer != null:
		var patience_ms: int = roundi(PongNetProtocol.LOAD_STALL_TIMEOUT_S * 1000.0)
		packet_peer.set_timeout(PongNetProtocol.TIMEOUT_LIMIT, patience_ms, patience_ms)


## Sets the timeouts of every connection of [param enet] from its round trip now: a
## [param server]'s to each client, a client's to the server once connected; a connection
## for which [param stalls] (Callable(peer) -> bool) holds bears a stall instead.
static func retune(
	enet: ENetMultiplayerPeer, api: SceneMultiplayer, server: bool, stalls: Callable
) -> void:
	if enet.get_connection_status() != MultiplayerPeer.CONNECTION_CONNECTED or api == null:
		return
	for id: int in api.get_peers() if server else PackedInt32Array([1]):
		if stalls.call(id):
			bear_stall(enet.get_peer(id))
		else:
			tune(enet.get_peer(id))


## Before this peer stalls: every connection bears it, and what is queued (the stall
## notice, the acknowledgements of what came in) leaves now rather than after the stall.
static func brace(enet: ENetMultiplayerPeer, api: SceneMultiplayer, server: bool) -> void:
	retune(enet, api, server, func(_peer: int) -> bool: return true)
	if enet.host != null:
		enet.host.flush()


## The silence that drops the peer at the end of [param path], from ENet's measures of its
## round trip and deviation (the ceiling when there is no such peer).
static func heartbeat_limit(path: ENetPacketPeer) -> float:
	if path == null:
		return PongNetProtocol.HEARTBEAT_TIMEOUT_MAX_S
	var rtt_ms: float = path.get_statistic(ENetPacketPeer.PEER_ROUND_TRIP_TIME)
	var jitter_ms: float = path.get_statistic(ENetPacketPeer.PEER_ROUND_TRIP_TIME_VARIANCE)
	return PongNetProtocol.heartbeat_timeout_s(rtt_ms / 1000.0, jitter_ms / 1000.0)


## Drops [param peers] of [param enet] at once (no goodbye awaited), then polls [param api]
## once, which reports them gone: until its next poll Godot would still list them, and a
## message to all would fail on each ("Parameter "peer" is null"). SceneMultiplayer's own
## disconnect_peer reports nothing (it blocks peer_disconnected), so a match would never
## learn that the peer left.
static func drop(api: SceneMultiplayer, enet: ENetMultiplayerPeer, peers: Array[int]) -> void:
	for peer: int in peers:
		var known: bool = api.get_peers().has(peer) or api.get_authenticating_peers().has(peer)
		if known:
			enet.get_peer(peer).peer_disconnect_now()
	api.poll()
