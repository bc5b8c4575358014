class_name PongNetEnet
extends RefCounted
## What [PongNetSession] does to Godot's ENet peers: their timeouts and throttle, the
## heartbeat's packets and limits, and dropping a peer at once.


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


## Sends a heartbeat (one byte, unreliable, its own channel) through [param api]: a server
## to every client, a client to the server once it has passed the version check. Ordered,
## so that ENet never hands over a beat older than a stall notice that followed it.
static func beat(api: SceneMultiplayer, server: bool) -> void:
	var ordered: MultiplayerPeer.TransferMode = MultiplayerPeer.TRANSFER_MODE_UNRELIABLE_ORDERED
	_send_watch(api, server, PongNetProtocol.PACKET_BEAT, ordered)


## Says to the same peers, reliably on the heartbeat's channel (no beat overtakes it), that
## this peer is about to stall.
static func send_stall(api: SceneMultiplayer, server: bool) -> void:
	_send_watch(api, server, PongNetProtocol.PACKET_STALL, MultiplayerPeer.TRANSFER_MODE_RELIABLE)


static func _send_watch(
	api: SceneMultiplayer, server: bool, kind: int, mode: MultiplayerPeer.TransferMode
) -> void:
	var packet: PackedByteArray = PackedByteArray([kind])
	for peer: int in api.get_peers():
		if server or peer == PongNetAuthority.SERVER_ID:
			api.send_bytes(packet, peer, mode, PongNetProtocol.CHANNEL_BEAT)


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
