class_name PongNetLatency
extends RefCounted
## How old a peer's messages are when they arrive here. The path's base delay is our leg to
## the server plus the sender's: a client's message to another client crosses both. The
## server measures a sender's leg itself; a client takes what the sender's streams report
## (kept for its other messages). A [PongNetClock] per sender follows the offset between
## its servo clock and ours.

var _session: PongNetSession = null
var _clocks: Dictionary[int, PongNetClock] = {}
# Each peer's one-way delay to the server, ms, as its ball states and poses last reported it.
var _legs: Dictionary[int, int] = {}


func _init(session: PongNetSession) -> void:
	_session = session


## The one-way delay between this peer and [param peer], ms: half the measured round trip.
func leg_ms(peer: int) -> int:
	return roundi(_session.round_trip_s(peer) * 500.0)


## One-way delay of our own leg to the server, ms (0 on the server).
func my_leg_ms() -> int:
	return leg_ms(PongNetAuthority.SERVER_ID)


## How old a message of [param sender] stamped with its servo time [param sent_at] is, s,
## here on the server when [param on_server]. [param reported_leg_ms]: the sender's leg as
## its message reports it (-1: none in this message).
func age_of(on_server: bool, sender: int, sent_at: float, reported_leg_ms: int = -1) -> float:
	if reported_leg_ms >= 0:
		_legs[sender] = reported_leg_ms
	var their_leg_ms: int = _legs.get(sender, 0)
	if on_server:
		their_leg_ms = leg_ms(sender)
	elif sender == PongNetAuthority.SERVER_ID:
		their_leg_ms = 0
	if not _clocks.has(sender):
		_clocks[sender] = PongNetClock.new()
	var clock: PongNetClock = _clocks[sender]
	clock.base_latency_s = (my_leg_ms() + their_leg_ms) / 1000.0
	return clock.observe(Time.get_ticks_usec() / 1e6, sent_at)
