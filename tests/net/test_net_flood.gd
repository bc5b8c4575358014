extends TestSuite
## The server's watch for floods of connection requests: the datagrams of its probe, the
## probe against a real ENet server on this machine's loopback (the slot ENet gives it, the
## slot it frees, no slot when all are held, and Godot never hearing of any), the flood's
## log lines (one when it starts, one when it is over), and a server nobody is connected to
## opening a new ENet host when strangers hold half its slots.

# More than PongNetFlood.FLOOD_SLOTS.
const SLOTS: int = 40

var _server: ENetMultiplayerPeer = null
var _api: SceneMultiplayer = null
var _port: int = 0
var _joined: Array[int] = []
var _attacker: PacketPeerUDP = null


func before_each() -> void:
	_joined.clear()
	_server = ENetMultiplayerPeer.new()
	_server.set_bind_ip("127.0.0.1")
	for attempt: int in 20:
		_port = 20000 + randi() % 20000
		if _server.create_server(_port, SLOTS) == OK:
			break
	_api = SceneMultiplayer.new()
	_api.multiplayer_peer = _server
	_api.peer_connected.connect(func(peer: int) -> void: _joined.append(peer))
	_attacker = PacketPeerUDP.new()
	_attacker.bind(0, "127.0.0.1")
	_attacker.set_dest_address("127.0.0.1", _port)


func after_each() -> void:
	_attacker.close()
	_api.multiplayer_peer = null
	_server.close()


# Crafted CONNECTs from the attacker's socket, each its own client to ENet, never answered.
func _flood(count: int) -> void:
	for i: int in count:
		_attacker.put_packet(PongNetSlotProbe.connect_datagram(1000 + i, 0.0))
	_pump(5)


func _pump(frames: int) -> void:
	for frame: int in frames:
		_api.poll()
		OS.delay_msec(2)


# The probe's reading once ENet has answered (or given up on) its request.
func _read(probe: PongNetSlotProbe) -> int:
	probe.send("127.0.0.1", _port, PongNetPulse.now_s())
	for frame: int in 1000:
		_pump(1)
		var reading: int = probe.poll(PongNetPulse.now_s())
		if reading != PongNetSlotProbe.WAITING:
			return reading
	return PongNetSlotProbe.WAITING


func test_the_probe_speaks_enet_1_3() -> void:
	var request: PackedByteArray = PongNetSlotProbe.connect_datagram(0xA1B2C3D4, 1.5)
	assert_eq(request.size(), 52, "a header with its sent time and a 48-byte CONNECT")
	assert_eq([request[0], request[1]], [0x8F, 0xFF], "sent time flag, peer id 0xFFF: nobody yet")
	assert_eq([request[2], request[3]], [0x05, 0xDC], "sent at 1500 ms")
	assert_eq(request[4], 0x82, "CONNECT, to be acknowledged")
	assert_eq(request.slice(44, 48), PackedByteArray([0xA1, 0xB2, 0xC3, 0xD4]), "the connect id")
	var goodbye: PackedByteArray = PongNetSlotProbe.disconnect_datagram(300, 2)
	assert_eq(goodbye, PackedByteArray([0x21, 0x2C, 0x04, 0xFF, 0, 0, 0, 0, 0, 0]), "slot 300")
	var verify: PackedByteArray = PackedByteArray([0x80, 0x00, 0x12, 0x34])
	verify.append_array([0x03, 0xFF, 0x00, 0x01, 0x00, 0x07, 0x01, 0x02])
	verify.resize(4 + 44)
	verify.encode_u32(4 + 40, 0x78563412)  # Little-endian bytes: 12 34 56 78 on the wire.
	assert_eq(PongNetSlotProbe.verified_slot(verify, 0x12345678), [7, 2], "slot 7, session 2")
	assert_eq(PongNetSlotProbe.verified_slot(verify, 0x12345679), [], "another request's")
	assert_eq(PongNetSlotProbe.verified_slot(verify.slice(0, 30), 0x12345678), [], "cut off")
	assert_eq(PongNetSlotProbe.verified_slot(PackedByteArray([1]), 0), [], "too short")


func test_the_probe_reads_the_slots_strangers_hold_and_frees_its_own() -> void:
	var probe: PongNetSlotProbe = PongNetSlotProbe.new()
	assert_eq(_read(probe), 0, "nobody: the first slot")
	assert_eq(_read(probe), 0, "the probe said goodbye: its slot was freed at once")
	_flood(5)
	assert_eq(_read(probe), 5, "five requests never followed up hold the first five slots")
	assert_eq(_read(probe), 5, "and again")
	_flood(SLOTS)
	assert_eq(_read(probe), PongNetSlotProbe.FULL, "every slot held: no answer")
	assert_eq(_joined, [], "Godot heard of none of them")
	probe.close()


func test_a_flood_is_logged_once_when_it_starts_and_once_when_it_is_over() -> void:
	var flood: PongNetFlood = PongNetFlood.new("*", 7420, 4095)
	assert_eq(flood.note(10.0, 3), "", "a few requests in the handshake are no flood")
	assert_eq(flood.note(11.0, PongNetFlood.FLOOD_SLOTS - 1), "")
	var start: String = flood.note(12.0, 40)
	assert_true(start.begins_with(PongNetFlood.START_LINE), start)
	assert_true(start.contains("40 of 4095"), start)
	assert_true(flood.flooding)
	var later: Array[String] = []
	for second: int in 60:
		# Slots held, then (a probe finding a slot just freed) a few, then many again.
		later.append(flood.note(13.0 + second, 3 if second % 7 == 0 else 2000 + second))
	assert_eq("".join(later), "", "said once")
	assert_eq(flood.peak, 2059)
	# The last high reading came at 72 s: over once it is more than QUIET_S (40 s) old.
	for second: int in 33:
		assert_eq(flood.note(80.0 + second, 2), "", "not over while a recent reading was high")
	var over: String = flood.note(113.0, 1)
	assert_true(over.begins_with(PongNetFlood.OVER_LINE), over)
	assert_true(over.contains("at most 2059"), over)
	assert_false(flood.flooding)
	assert_true(flood.note(114.0, 100).begins_with(PongNetFlood.START_LINE), "a new flood")
	var full: String = PongNetFlood.new("*", 7420, SLOTS).note(1.0, SLOTS, true)
	assert_true(full.contains("ENet gave no slot to a request of ours"), full)


func test_a_server_nobody_is_connected_to_opens_a_new_host_when_strangers_hold_half() -> void:
	var flood: PongNetFlood = PongNetFlood.new("127.0.0.1", _port, SLOTS)
	_flood(SLOTS >> 1)
	var peer: ENetMultiplayerPeer = _server
	for frame: int in 2000:
		peer = flood.frame(peer, _api)
		if peer != _server:
			break
		_pump(1)
	assert_true(peer != null and peer != _server, "a new host")
	assert_true(flood.flooding, "the flood was noticed first")
	assert_eq(flood.renewals, 1)
	assert_eq(_api.multiplayer_peer, peer, "the game's multiplayer uses it")
	_server = peer
	var probe: PongNetSlotProbe = PongNetSlotProbe.new()
	assert_eq(_read(probe), 0, "every slot free again, on the same port")
	probe.close()
	flood.close()


func test_a_server_somebody_is_connected_to_keeps_its_host() -> void:
	var client: ENetMultiplayerPeer = ENetMultiplayerPeer.new()
	client.create_client("127.0.0.1", _port)
	for frame: int in 500:
		client.poll()
		_pump(1)
		if not _joined.is_empty():
			break
	assert_eq(_joined.size(), 1, "a player is connected")
	var flood: PongNetFlood = PongNetFlood.new("127.0.0.1", _port, SLOTS)
	_flood(SLOTS - 2)
	var peer: ENetMultiplayerPeer = _server
	for frame: int in 600:
		client.poll()
		peer = flood.frame(peer, _api)
		_pump(1)
	assert_eq(peer, _server, "the player keeps its connection")
	assert_true(flood.flooding)
	assert_eq(flood.renewals, 0)
	client.close()
	flood.close()
