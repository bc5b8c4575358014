class_name PongNetEnet
extends RefCounted
## What [PongNetSession] does to Godot's ENet peers: their timeouts and throttle, the
## heartbeat's limits, and dropping a peer at once.


## Gives [param packet_peer] ENet's patience ([constant PongNetProtocol.ENET_PATIENCE_MS]:
## the heartbeat decides who is gone) and keeps its throttle open.
static func tune(packet_peer: ENetPacketPeer) -> void:
	if packet_peer == null:
		return
	var patience: int = PongNetProtocol.ENET_PATIENCE_MS
	packet_peer.set_timeout(PongNetProtocol.TIMEOUT_LIMIT, patience, patience)
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


## Before this peer stalls: what is queued (the stall notice, the acknowledgements of what
## came in) leaves now rather than after the stall.
static func brace(enet: ENetMultiplayerPeer) -> void:
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


## Whether a packet to [param peer] can leave through [param api] now. Godot lists a peer until
## it reports it gone, and it reports the peers that went in one poll one at a time: while a
## handler of the first runs, the next may already be reset, and a send to it fails
## ("Unable to send packet on channel 4, max channels: 0").
static func can_send(api: MultiplayerAPI, peer: int) -> bool:
	if not api.get_peers().has(peer):
		return false
	var enet: ENetMultiplayerPeer = api.multiplayer_peer as ENetMultiplayerPeer
	if enet == null:
		return true
	var path: ENetPacketPeer = enet.get_peer(peer)
	return path != null and path.get_state() == ENetPacketPeer.STATE_CONNECTED


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
