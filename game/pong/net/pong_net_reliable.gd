class_name PongNetReliable
extends RefCounted
## Reliable, in-order delivery of raw packets to each peer over unreliable datagrams, with a
## resend wait that never grows past [constant MAX_RESEND_S]. ENet's own reliable channels
## double the wait after every lost try without a cap: after a 5 s Wi-Fi hiccup the next try
## of a packet sent during it came 15 s after the path was back, and every later packet of
## its channel waited behind it (docs/pong-networking.md, "Outages"). Here a lost packet is
## tried again within a quarter of a second of the path's return.
## [br]Each packet to a peer carries a sequence number ([constant DATA_ID], seq, the
## packet); the peer answers with the next one it expects ([constant ACK_ID], a cumulative
## acknowledgement), delivers in order and holds what arrived early. The oldest
## [constant WINDOW] unacknowledged packets are resent when their wait is over, the wait
## doubling from the round trip up to the cap. Times are seconds of a clock the caller
## passes in, so the rules can be tested without waiting.

## Layout ids of the two packets ("RELY", "ACKS"; no message layout of the schema uses them).
const DATA_ID: int = 0x52454C59
const ACK_ID: int = 0x41434B53
## Unacknowledged packets resent at a time, oldest first (a receiver cannot deliver the
## newer ones before them anyway).
const WINDOW: int = 64
## Packets a receiver holds ahead of the next it expects; more is a bad message.
const MAX_AHEAD: int = 4096
const MIN_RESEND_S: float = 0.1
const MAX_RESEND_S: float = 0.25

## Sends a raw packet unreliably: Callable(peer: int, packet: PackedByteArray).
var transmit: Callable = Callable()
## Hands a delivered packet on, in order: Callable(peer: int, packet: PackedByteArray).
var deliver: Callable = Callable()
## The round trip to a peer in seconds, 0 when unknown: Callable(peer: int) -> float.
var round_trip_of: Callable = Callable()

# Per peer: the next sequence to give, and what is unacknowledged, seq -> Outgoing.
var _next: Dictionary[int, int] = {}
var _unacked: Dictionary[int, Dictionary] = {}
# Per peer: the next sequence to deliver, and what arrived early, seq -> packet.
var _expected: Dictionary[int, int] = {}
var _early: Dictionary[int, Dictionary] = {}
# Peers owed an acknowledgement at the next poll.
var _ack_due: Dictionary[int, bool] = {}


class Outgoing:
	var packet: PackedByteArray
	var sent_s: float = -INF
	var wait_s: float = 0.0
	var tries: int = 0

	func _init(p_packet: PackedByteArray) -> void:
		packet = p_packet


## Sends [param payload] to [param peer] reliably, at [param now_s]; the first try as
## [param copies] datagrams at once.
func send(peer: int, payload: PackedByteArray, now_s: float, copies: int = 1) -> void:
	var seq: int = _next.get(peer, 0)
	_next[peer] = seq + 1
	var packet: PackedByteArray = PackedByteArray()
	packet.resize(8)
	packet.encode_u32(0, DATA_ID)
	packet.encode_u32(4, seq)
	packet.append_array(payload)
	var outgoing: Outgoing = Outgoing.new(packet)
	var unacked: Dictionary = _unacked.get_or_add(peer, {})
	unacked[seq] = outgoing
	_try(peer, outgoing, now_s)
	# A lost try waits a resend (up to MAX_RESEND_S); the receiver takes a copy once.
	for _copy: int in copies - 1:
		transmit.call(peer, packet)


## Whether [param packet] is one of ours (a data packet or an acknowledgement).
static func owns(packet: PackedByteArray) -> bool:
	return packet.size() >= 4 and packet.decode_u32(0) in [DATA_ID, ACK_ID]


## A packet of ours from [param peer]: "" when taken, else why it is bad.
func receive(peer: int, packet: PackedByteArray) -> String:
	if packet.size() < 8:
		return "%d bytes: no sequence number" % packet.size()
	var number: int = packet.decode_u32(4)
	if packet.decode_u32(0) == ACK_ID:
		return _acknowledged(peer, number) if packet.size() == 8 else "a long ack"
	var expected: int = _expected.get(peer, 0)
	_ack_due[peer] = true
	var why: String = ""
	if number >= expected + MAX_AHEAD:
		why = "packet %d is %d ahead of %d" % [number, number - expected, expected]
	elif number >= expected:  # Below: again, its acknowledgement was lost.
		var early: Dictionary = _early.get_or_add(peer, {})
		early[number] = packet.slice(8)
		why = _deliver_in_order(peer, early)
	return why


# Delivers what [param early] holds from the next expected packet of [param peer] on.
func _deliver_in_order(peer: int, early: Dictionary) -> String:
	var expected: int = _expected.get(peer, 0)
	while early.has(expected):
		var payload: PackedByteArray = early[expected]
		early.erase(expected)
		expected += 1
		_expected[peer] = expected
		if owns(payload):
			return "a packet of ours inside one"
		deliver.call(peer, payload)
		if not _expected.has(peer):
			break  # The delivery made us forget the peer (it left).
	return ""


## Sends the acknowledgements owed and resends what waited long enough, at [param now_s].
func poll(now_s: float) -> void:
	for peer: int in _ack_due.keys():
		var ack: PackedByteArray = PackedByteArray()
		ack.resize(8)
		ack.encode_u32(0, ACK_ID)
		var next: int = _expected.get(peer, 0)
		ack.encode_u32(4, next)
		transmit.call(peer, ack)
	_ack_due.clear()
	for peer: int in _unacked.keys():
		var unacked: Dictionary = _unacked[peer]
		var resent: int = 0
		for seq: int in unacked.keys():  # In the order sent: oldest first.
			if resent >= WINDOW:
				break
			var outgoing: Outgoing = unacked[seq]
			if now_s - outgoing.sent_s >= outgoing.wait_s:
				_try(peer, outgoing, now_s)
			resent += 1


## Packets to [param peer] not yet acknowledged.
func unacknowledged(peer: int) -> int:
	var unacked: Dictionary = _unacked.get(peer, {})
	return unacked.size()


## Forgets [param peer] (gone); 0 forgets everyone.
func forget(peer: int) -> void:
	for table: Dictionary in [_next, _unacked, _expected, _early, _ack_due]:
		if peer == 0:
			table.clear()
		else:
			table.erase(peer)


func _try(peer: int, outgoing: Outgoing, now_s: float) -> void:
	var round_trip: float = round_trip_of.call(peer) if round_trip_of.is_valid() else 0.0
	var base: float = clampf(2.0 * round_trip + 0.05, MIN_RESEND_S, MAX_RESEND_S)
	var waited: float = minf(2.0 * outgoing.wait_s, MAX_RESEND_S)
	outgoing.wait_s = base if outgoing.tries == 0 else maxf(base, waited)
	outgoing.tries += 1
	outgoing.sent_s = now_s
	transmit.call(peer, outgoing.packet)


func _acknowledged(peer: int, next: int) -> String:
	if next > _next.get(peer, 0):
		return "an ack of packet %d, never sent" % (next - 1)
	var unacked: Dictionary = _unacked.get(peer, {})
	var progress: bool = false
	for seq: int in unacked.keys():
		if seq >= next:
			break
		unacked.erase(seq)
		progress = true
	if not progress:
		return ""
	# The path carries again: what was tried more than once during the loss goes now, not
	# when its grown wait is over.
	var window: int = 0
	for seq: int in unacked.keys():
		var outgoing: Outgoing = unacked[seq]
		if outgoing.tries > 1:
			outgoing.tries = 0
			outgoing.sent_s = -INF
		window += 1
		if window >= WINDOW:
			break
	return ""
