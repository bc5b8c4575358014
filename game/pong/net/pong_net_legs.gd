class_name PongNetLegs
extends RefCounted
## Each direction's share of the round trip between this peer and a peer whose heartbeat it
## hears (a client and its server). Timing alone cannot tell one direction from the other
## (only the round trip is observable), so each beat carries the sender's system clock: on
## machines whose clocks are set by NTP, arrival minus that stamp is the one-way delay plus
## their clocks' small difference. The fastest of the recent beats stands for each
## direction; each side tells the other what it measured, and the round trip is split in
## the ratio of the two. A split the clocks cannot have made (a direction faster than
## [constant NEGATIVE_MS] below zero, or two legs longer than [constant LONGEST_RATIO] round
## trips) falls back to half each way, as does a peer not yet measured both ways
## (docs/pong-networking.md, "Clocks").

## Beats remembered per peer (5 s at the heartbeat's rate).
const WINDOW: int = 25
## How far below zero a measured leg may read before the two clocks are taken to disagree,
## ms (NTP keeps machines' clocks within tens of ms of each other, usually far closer).
const NEGATIVE_MS: float = 20.0
## The two measured legs together may exceed the round trip by this factor, plus
## [constant NEGATIVE_MS] (the round trip is ENet's smoothed mean, the legs the fastest).
const LONGEST_RATIO: float = 2.0

# Per peer: the one-way delays of its recent beats to us, ms (our clock minus its stamp).
var _inbound: Dictionary[int, PackedFloat64Array] = {}
# Per peer: the fastest of our beats to it, as it last told us, ms.
var _outbound: Dictionary[int, float] = {}


## This machine's system clock, s (the stamp a beat carries).
static func wall_s() -> float:
	return Time.get_unix_time_from_system()


## A beat of [param peer] stamped [param sent_wall_s] (its system clock) arrived at
## [param now_wall_s]; [param heard_ms] is what it measured of ours (NAN: nothing yet).
func heard(peer: int, now_wall_s: float, sent_wall_s: float, heard_ms: float) -> void:
	var delay_ms: float = (now_wall_s - sent_wall_s) * 1000.0
	if not is_finite(delay_ms):
		return
	var samples: PackedFloat64Array = _inbound.get(peer, PackedFloat64Array())
	samples.append(delay_ms)
	if samples.size() > WINDOW:
		samples.remove_at(0)
	_inbound[peer] = samples
	if is_finite(heard_ms):
		_outbound[peer] = heard_ms


## What this peer tells [param peer] of its beats' delay to us, ms (NAN: none heard).
func inbound_ms(peer: int) -> float:
	var samples: PackedFloat64Array = _inbound.get(peer, PackedFloat64Array())
	if samples.is_empty():
		return NAN
	var fastest: float = INF
	for delay_ms: float in samples:
		fastest = minf(fastest, delay_ms)
	return fastest


## The round trip [param round_trip_s] to [param peer] split into the delay towards it (x)
## and from it (y), s.
func split(peer: int, round_trip_s: float) -> Vector2:
	var half: Vector2 = Vector2(round_trip_s, round_trip_s) * 0.5
	var inbound: float = inbound_ms(peer)
	var outbound: float = _outbound.get(peer, NAN)
	if not (is_finite(inbound) and is_finite(outbound)):
		return half
	if minf(inbound, outbound) < -NEGATIVE_MS:
		return half
	inbound = maxf(inbound, 0.0)
	outbound = maxf(outbound, 0.0)
	var both: float = inbound + outbound
	if both <= 0.0 or both > LONGEST_RATIO * round_trip_s * 1000.0 + NEGATIVE_MS:
		return half
	return Vector2(outbound, inbound) / both * round_trip_s


## Forgets [param peer] (gone).
func forget(peer: int) -> void:
	_inbound.erase(peer)
	_outbound.erase(peer)
