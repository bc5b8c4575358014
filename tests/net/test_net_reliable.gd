extends TestSuite
## Reliable delivery of our own (PongNetReliable) between two ends over a simulated path that
## loses, reorders, duplicates and goes dead for a while: every message arrives once, in
## order, and a path that comes back carries the backlog within a second; what a hostile peer
## sends is a bad message, never a delivery.

const A: int = 1
const B: int = 42
const STEP_S: float = 0.01
const PATH_S: float = 0.03


## One direction of the simulated path: datagrams in flight with their arrival times.
class Wire:
	var in_flight: Array[Array] = []
	var rng: RandomNumberGenerator = RandomNumberGenerator.new()
	var loss: float = 0.0
	var dead: bool = false
	var now_s: float = 0.0
	var sent: int = 0
	## Datagrams still to lose, whatever else the path does.
	var lose_next: int = 0

	func carry(packet: PackedByteArray) -> void:
		sent += 1
		if lose_next > 0:
			lose_next -= 1
			return
		if dead or rng.randf() < loss:
			return
		var copies: int = 2 if rng.randf() < 0.05 else 1
		for _copy: int in copies:
			in_flight.append([now_s + PATH_S + rng.randf() * 0.02, packet])

	func due(at_s: float) -> Array[PackedByteArray]:
		var out: Array[PackedByteArray] = []
		if dead:  # What was on its way is lost too.
			in_flight.clear()
			return out
		var kept: Array[Array] = []
		for item: Array in in_flight:
			if item[0] <= at_s:
				out.append(item[1])
			else:
				kept.append(item)
		in_flight = kept
		return out


var _got: Array[int] = []


func _pair(ab: Wire, ba: Wire) -> Array[PongNetReliable]:
	var a: PongNetReliable = PongNetReliable.new()
	var b: PongNetReliable = PongNetReliable.new()
	a.transmit = func(_peer: int, packet: PackedByteArray) -> void: ab.carry(packet)
	b.transmit = func(_peer: int, packet: PackedByteArray) -> void: ba.carry(packet)
	b.deliver = func(_peer: int, payload: PackedByteArray) -> void:
		_got.append(payload.decode_u32(0))
	a.deliver = func(_peer: int, _bytes: PackedByteArray) -> void: pass
	return [a, b]


func _payload(n: int) -> PackedByteArray:
	var bytes: PackedByteArray = PackedByteArray()
	bytes.resize(4)
	bytes.encode_u32(0, n)
	return bytes


# Runs the two ends from [param from_s] to [param to_s]; a sends one message every
# [param every] steps until [param last] messages were sent (counted in [param sent]).
func _run(
	ends: Array[PongNetReliable],
	wires: Array[Wire],
	from_s: float,
	to_s: float,
	sent: Array[int],
	last: int
) -> void:
	var t: float = from_s
	var step: int = 0
	while t < to_s:
		for wire: Wire in wires:
			wire.now_s = t
		if sent[0] < last and step % 3 == 0:
			ends[0].send(B, _payload(sent[0]), t)
			sent[0] += 1
		for packet: PackedByteArray in wires[0].due(t):
			assert_eq(ends[1].receive(A, packet), "")
		for packet: PackedByteArray in wires[1].due(t):
			assert_eq(ends[0].receive(B, packet), "")
		ends[0].poll(t)
		ends[1].poll(t)
		t += STEP_S
		step += 1


func before_each() -> void:
	_got.clear()


func test_every_message_arrives_once_and_in_order_over_a_lossy_reordering_path() -> void:
	var wires: Array[Wire] = [Wire.new(), Wire.new()]
	for wire: Wire in wires:
		wire.rng.seed = 7
		wire.loss = 0.3
	var ends: Array[PongNetReliable] = _pair(wires[0], wires[1])
	var sent: Array[int] = [0]
	_run(ends, wires, 0.0, 12.0, sent, 300)
	var expected: Array[int] = []
	for n: int in 300:
		expected.append(n)
	assert_eq(_got, expected, "all 300, once each, in order, at 30 % loss each way")
	assert_eq(ends[0].unacknowledged(B), 0, "and all acknowledged")


func test_a_message_sent_twice_whose_first_datagram_is_lost_arrives_without_a_resend() -> void:
	var wires: Array[Wire] = [Wire.new(), Wire.new()]
	var ends: Array[PongNetReliable] = _pair(wires[0], wires[1])
	# The path loses the first datagram of the message, and nothing after it.
	wires[0].lose_next = 1
	ends[0].send(B, _payload(5), 0.0, 2)
	var sent: Array[int] = [1]
	_run(ends, wires, 0.0, PATH_S + 0.03, sent, 1)
	assert_eq(_got, [5] as Array[int], "there within one path time, no resend waited")
	assert_eq(wires[0].sent, 2, "two datagrams: the message and its copy, nothing resent")


func test_a_path_dead_for_10_s_carries_the_backlog_within_a_second_of_its_return() -> void:
	var wires: Array[Wire] = [Wire.new(), Wire.new()]
	var ends: Array[PongNetReliable] = _pair(wires[0], wires[1])
	var sent: Array[int] = [0]
	_run(ends, wires, 0.0, 1.0, sent, 1000)
	var before: int = _got.size()
	for wire: Wire in wires:
		wire.dead = true
	var carried_before: int = wires[0].sent
	_run(ends, wires, 1.0, 11.0, sent, 1000)
	# While the path is dead: the oldest WINDOW messages are tried at most every
	# MAX_RESEND_S, besides each new message's first try.
	var tries: int = wires[0].sent - carried_before
	var rounds: float = 10.0 / PongNetReliable.MAX_RESEND_S + 1.0
	var bound: float = (sent[0] - before) + rounds * PongNetReliable.WINDOW
	assert_lt(tries, roundi(bound), "no flood into a dead path")
	assert_eq(_got.size(), before, "nothing crossed")
	for wire: Wire in wires:
		wire.dead = false
	var backlog: int = sent[0]
	_run(ends, wires, 11.0, 12.0, sent, backlog)
	assert_eq(_got.size(), backlog, "every message of the outage, within a second")
	for n: int in mini(backlog, _got.size()):
		assert_eq(_got[n], n)


func test_what_a_hostile_peer_sends_is_a_bad_message_and_delivers_nothing() -> void:
	var wires: Array[Wire] = [Wire.new(), Wire.new()]
	var ends: Array[PongNetReliable] = _pair(wires[0], wires[1])
	var b: PongNetReliable = ends[1]
	assert_ne(b.receive(A, PackedByteArray([0x59, 0x4C, 0x45, 0x52])), "", "cut off")
	var ahead: PackedByteArray = PackedByteArray()
	ahead.resize(12)
	ahead.encode_u32(0, PongNetReliable.DATA_ID)
	ahead.encode_u32(4, PongNetReliable.MAX_AHEAD + 5)
	assert_ne(b.receive(A, ahead), "", "far ahead: it would hold without end")
	var nested: PackedByteArray = PackedByteArray()
	nested.resize(8)
	nested.encode_u32(0, PongNetReliable.DATA_ID)
	nested.encode_u32(4, 0)
	nested.append_array(nested.duplicate())
	assert_ne(b.receive(A, nested), "", "a packet of ours inside one")
	var ack: PackedByteArray = PackedByteArray()
	ack.resize(8)
	ack.encode_u32(0, PongNetReliable.ACK_ID)
	ack.encode_u32(4, 9)
	assert_ne(ends[0].receive(B, ack), "", "an ack of what was never sent")
	assert_eq(_got, [] as Array[int])
	assert_true(PongNetReliable.owns(ack))
	assert_false(PongNetReliable.owns(PackedByteArray([1, 2, 3, 4, 5])), "a message's layout")


func test_no_message_layout_is_taken_for_one_of_ours() -> void:
	for schema_id: int in PongNetFacts.message_decoders():
		assert_false(schema_id in [PongNetReliable.DATA_ID, PongNetReliable.ACK_ID], str(schema_id))
