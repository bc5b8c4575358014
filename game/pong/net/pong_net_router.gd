class_name PongNetRouter
extends Node
## The one way networked Pong's messages come and go. Each is a [PongNetMessage], sent as a
## raw packet ([method SceneMultiplayer.send_bytes]) on its own channel in its own transfer
## mode, both defined in the schema. Each packet received ([signal
## SceneMultiplayer.peer_packet], its sender's id as Godot knows it: a relayed packet names its
## source, which only the server writes) is decoded by its layout id (its first four bytes)
## with its class's [code]decode()[/code], which checks every field against the schema; then
## it must come from the server if only the server sends it, and reach the server if only the
## server takes it; then it goes to the handler the node that owns its state registered
## ([method handle]), typed. Anything else (too short, an unknown layout, a field out of its
## limits, a wrong sender or receiver) is one of the sender's bad messages
## ([method PongNetSession.misbehaved]), never an engine error: no RPC is involved, so no wrong
## count or type of arguments can reach Godot's RPC layer (docs/networking.md, "Raw packets").
## A message of a known layout that nobody handles now (a match's message between matches) is
## dropped quietly.
## [br]Until a peer has been heard from, its reliable messages go on the handshake's channel
## and its unreliable ones are not sent: Godot admits a peer once each side has had the
## other's "auth complete" (that channel, reliable) and throws away, with an engine error,
## anything the other side sends before its own has arrived. A beat on another channel
## overtook a resent "complete" on a lossy path that reorders. Each side greets a peer that
## connects with one reliable beat behind the "complete"; a peer's first raw packet shows that
## it has admitted us. (Unreliable messages sent reliably instead queued behind a lost one
## for ENet's first resend, over a second: the heartbeat took the server for dead.)
## [br]Once a peer has been heard from, the reliable channel's messages to it go through
## [member reliable] ([PongNetReliable]) as unreliable datagrams with resends of our own:
## ENet's reliable channels stalled for as long as a Wi-Fi hiccup had lasted, or longer.
## [br]A client's message to every peer reaches the server only; the node that accepts it
## there forwards it to the other clients ([method forward], [PongNetForward]), so what the
## server refused never reaches them.

## Where bad messages are counted, and whether this peer is the server: the session the
## router is a child of.
var session: PongNetSession = null

## The reliable channel's messages to a peer heard from travel through it
## ([PongNetReliable]: resends that never wait longer than a quarter of a second).
var reliable: PongNetReliable = PongNetReliable.new()
## Server: the messages forwarded, per origin and kind ("ORIGIN LABEL"), for a test's report.
var forwarded: Dictionary[String, int] = {}

var _decoders: Dictionary[int, Callable] = PongNetFacts.message_decoders()
var _handlers: Dictionary[int, Callable] = {}
# Peers a raw packet has come from (see the class description).
var _heard: Dictionary[int, bool] = {}


func _init() -> void:
	reliable.transmit = _transmit
	reliable.deliver = _dispatch
	reliable.round_trip_of = _round_trip_s


func _process(_delta: float) -> void:
	if _connected():
		reliable.poll(_now_s())


func _enter_tree() -> void:
	var parent: PongNetSession = get_parent() as PongNetSession
	if parent != null:
		session = parent
	if not multiplayer.peer_connected.is_connected(_greet):
		multiplayer.peer_connected.connect(_greet)


func _exit_tree() -> void:
	if multiplayer.peer_connected.is_connected(_greet):
		multiplayer.peer_connected.disconnect(_greet)


## From now on, messages of layout [param schema_id] go to [param handler], a
## Callable(sender: int, message) whose message parameter has that layout's class (one handler
## a layout: the last one registered).
func handle(schema_id: int, handler: Callable) -> void:
	_handlers[schema_id] = handler


## Messages stop going to the handlers of [param listener] (its match is over).
func forget(listener: Object) -> void:
	for schema_id: int in _handlers.keys():
		if _handlers[schema_id].get_object() == listener:
			_handlers.erase(schema_id)


## Sends [param message] to every other peer (a client's to the server, which forwards it);
## a reliable one's first try as [param copies] datagrams (a message whose delay the players
## see: the ball's transfer).
func send_all(message: PongNetMessage, copies: int = 1) -> void:
	if not _connected():
		return
	var each: bool = message.channel() == PongNetFacts.NET_CHANNEL_RELIABLE
	for peer: int in multiplayer.get_peers():
		each = each or not _heard.has(peer)
	if not each:
		_send(message, MultiplayerPeer.TARGET_PEER_BROADCAST)
		return
	for peer: int in multiplayer.get_peers():
		if PongNetEnet.can_send(multiplayer, peer):
			_send(message, peer, copies)


## Forgets what was heard from [param peer] (gone; 0: every peer, the session closed).
func forget_peer(peer: int) -> void:
	reliable.forget(peer)
	if peer == 0:
		_heard.clear()
	else:
		_heard.erase(peer)


## Sends [param message] to [param peer] while it is connected (to a peer just gone the engine
## would log an error: [method PongNetEnet.can_send]).
func send_to(peer: int, message: PongNetMessage) -> void:
	if _reaches(peer):
		_send(message, peer)


## Server: sends [param message], which the client [param origin] sent to every peer and the
## node that owns its state accepted, on to the other clients, on its own channel.
func forward(origin: int, message: PongNetMessage) -> void:
	if not _connected() or not session.is_server or origin == PongNetAuthority.SERVER_ID:
		return
	var packet: PackedByteArray = PongNetForward.wrap(origin, message.encode())
	var key: String = "%d %s" % [origin, message.label()]
	forwarded[key] = forwarded.get(key, 0) + 1
	for peer: int in multiplayer.get_peers():
		if peer != origin:
			_send_packet(packet, peer, message.channel(), message.transfer_mode())


## A raw packet from [param sender] ([signal SceneMultiplayer.peer_packet]).
func receive(sender: int, packet: PackedByteArray) -> void:
	_heard[sender] = true
	if PongNetReliable.owns(packet):
		var why: String = reliable.receive(sender, packet)
		if not why.is_empty():
			_bad(sender, "reliable packet", why)
		return
	_dispatch(sender, packet)


# A message's bytes from [param sender], decoded, checked and handed to its handler.
func _dispatch(sender: int, packet: PackedByteArray) -> void:
	if PongNetForward.owns(packet):
		_unwrap(sender, packet)
		return
	if packet.size() < 4:
		_bad(sender, "message", "%d bytes: no layout id" % packet.size())
		return
	var schema_id: int = packet.decode_u32(0)
	var decoder: Callable = _decoders.get(schema_id, Callable())
	if not decoder.is_valid():
		_bad(sender, "message", "layout %08x is none of this version's messages" % schema_id)
		return
	var label: String = PongNetFacts.MESSAGE_LABELS[schema_id]
	var message: PongNetMessage = decoder.call(packet)
	if message == null:
		_bad(sender, label, HapticsWireReader.last_error)
		return
	if message.from_server() and sender != PongNetAuthority.SERVER_ID:
		_bad(sender, label, "only the server sends it")
		return
	if message.to_server() and not session.is_server:
		_bad(sender, label, "only the server takes it")
		return
	var handler: Callable = _handlers.get(schema_id, Callable())
	if handler.is_valid():
		handler.call(sender, message)


# A forward from [param sender]: its message, dispatched as its origin's.
func _unwrap(sender: int, packet: PackedByteArray) -> void:
	var origin: int = PongNetForward.origin_of(packet)
	var inner: PackedByteArray = PongNetForward.inner(packet)
	var why: String = ""
	if session.is_server or sender != PongNetAuthority.SERVER_ID:
		why = "only the server forwards messages"
	elif origin <= PongNetAuthority.SERVER_ID or origin == multiplayer.get_unique_id():
		why = "forwarded from peer %d" % origin
	elif PongNetForward.owns(inner):
		why = "a forward inside a forward"
	if not why.is_empty():
		_bad(sender, "forward", why)
		return
	_dispatch(origin, inner)


func _send(message: PongNetMessage, peer: int, copies: int = 1) -> void:
	_send_packet(message.encode(), peer, message.channel(), message.transfer_mode(), copies)


func _send_packet(
	packet: PackedByteArray, peer: int, channel: int, mode: int, copies: int = 1
) -> void:
	var api: SceneMultiplayer = multiplayer as SceneMultiplayer
	if channel == PongNetFacts.NET_CHANNEL_RELIABLE and _heard.has(peer):
		reliable.send(peer, packet, _now_s(), copies)
	elif peer == MultiplayerPeer.TARGET_PEER_BROADCAST or _heard.has(peer):
		api.send_bytes(packet, peer, mode, channel)
	elif mode == MultiplayerPeer.TRANSFER_MODE_RELIABLE:
		api.send_bytes(
			packet, peer, MultiplayerPeer.TRANSFER_MODE_RELIABLE, PongNetFacts.NET_CHANNEL_HANDSHAKE
		)


# A peer just connected: one reliable beat behind Godot's "auth complete", so that it hears
# from us even if nothing else is sent to it (see the class description).
func _greet(peer: int) -> void:
	if _reaches(peer):
		var beat: PongNetBeatMessage = PongNetBeatMessage.new()
		beat.wall_s = PongNetLegs.wall_s()
		(multiplayer as SceneMultiplayer).send_bytes(
			beat.encode(),
			peer,
			MultiplayerPeer.TRANSFER_MODE_RELIABLE,
			PongNetFacts.NET_CHANNEL_HANDSHAKE
		)


# The round trip to [param peer] (a client reaches only its server).
func _round_trip_s(peer: int) -> float:
	return session.round_trip_s(peer) if session != null else 0.0


# One of our reliable packets, unreliably, on the reliable channel.
func _transmit(peer: int, packet: PackedByteArray) -> void:
	if _reaches(peer):
		(multiplayer as SceneMultiplayer).send_bytes(
			packet,
			peer,
			MultiplayerPeer.TRANSFER_MODE_UNRELIABLE,
			PongNetFacts.NET_CHANNEL_RELIABLE
		)


static func _now_s() -> float:
	return Time.get_ticks_usec() / 1e6


# Whether a packet to [param peer] leaves now: our session open and the peer still connected.
func _reaches(peer: int) -> bool:
	return _connected() and PongNetEnet.can_send(multiplayer, peer)


func _connected() -> bool:
	if session == null or not session.is_open() or not is_inside_tree():
		return false
	var peer: MultiplayerPeer = multiplayer.multiplayer_peer
	return peer != null and peer.get_connection_status() == MultiplayerPeer.CONNECTION_CONNECTED


func _bad(sender: int, what: String, reason: String) -> void:
	if session != null:
		session.misbehaved(sender, what, reason)
