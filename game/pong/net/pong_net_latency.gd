class_name PongNetLatency
extends RefCounted
## How old a peer's messages are when they arrive here. The path's base delay is the
## sender's leg to the server plus the server's to us: a client's message to another client
## crosses both. Each leg is its direction's share of the round trip ([PongNetLegs]: on an
## asymmetric path the two differ). The server measures a sender's leg itself; a client takes
## what the sender's streams report (kept for its other messages). A [PongNetClock] per
## sender follows the offset between its servo clock and ours.

var _session: PongNetSession = null
var _clocks: Dictionary[int, PongNetClock] = {}
# Each peer's one-way delay to the server, ms, as its ball states and poses last reported it.
var _legs: Dictionary[int, int] = {}


func _init(session: PongNetSession) -> void:
	_session = session


## The delay from this peer to the server, ms (0 on the server).
func up_ms() -> int:
	return roundi(_split(PongNetAuthority.SERVER_ID).x * 1000.0)


## The delay from the server to this peer, ms (0 on the server).
func down_ms() -> int:
	return roundi(_split(PongNetAuthority.SERVER_ID).y * 1000.0)


## How long our paddle's pose may take to reach a master and its state to come back, s: a
## round trip through the server (on the server, to the farthest client).
func touch_reach_s() -> float:
	var peers: PackedInt32Array = [PongNetAuthority.SERVER_ID]
	if _session.is_server:
		peers = _session.multiplayer.get_peers()
	var most: float = 0.0
	for peer: int in peers:
		most = maxf(most, _session.round_trip_s(peer))
	return most


## On the server: the delay from [param peer] to it, ms.
func from_ms(peer: int) -> int:
	return roundi(_split(peer).y * 1000.0)


## How old a message of [param sender] stamped with its servo time [param sent_at] is, s,
## here on the server when [param on_server]. [param reported_leg_ms]: the sender's leg as
## its message reports it (-1: none in this message).
func age_of(on_server: bool, sender: int, sent_at: float, reported_leg_ms: int = -1) -> float:
	if reported_leg_ms >= 0:
		_legs[sender] = reported_leg_ms
	var their_leg_ms: int = _legs.get(sender, 0)
	if on_server:
		their_leg_ms = from_ms(sender)
	elif sender == PongNetAuthority.SERVER_ID:
		their_leg_ms = 0
	if not _clocks.has(sender):
		_clocks[sender] = PongNetClock.new()
	var clock: PongNetClock = _clocks[sender]
	clock.base_latency_s = (down_ms() + their_leg_ms) / 1000.0
	return clock.observe(Time.get_ticks_usec() / 1e6, sent_at)


# The round trip to [param peer] split into the delay towards it (x) and from it (y), s.
func _split(peer: int) -> Vector2:
	return _session.pulse.legs.split(peer, _session.round_trip_s(peer))
