class_name PongNetClock
extends RefCounted
## How old a received stream state is, without synchronised clocks. Each state carries
## the sender's servo time; the difference to our receive time is a constant offset plus
## the path's delay. The smallest difference seen recently stands for the fastest path;
## a state that took longer (jitter, queueing) is older by the excess. The fastest path's
## own delay comes from ENet's round trip ([member base_latency_s], half of it per leg).
## [br]A stamp is taken only when it fits: one that would have arrived more than
## [constant LEEWAY_S] faster than the fastest path seen is refused ([method observe] returns
## [constant REFUSED]), so a forged stamp cannot become the minimum that every later state
## is aged from (one stamp of 9.9e6 s made 1,239 of 1,594 honest states look millions of
## seconds old). A minimum that every state of a run of [constant RUN] reads as more than
## [constant STALE_S] old was itself a forgery or a jump of the sender's clock: it is
## replaced by the run's.

## [method observe]'s answer for a stamp that does not fit.
const REFUSED: float = -1.0
## How much faster than the fastest path seen a state may arrive, seconds. An honest
## sender's servo clock can jump by seconds (it starts over with a match, or catches up
## after a stall): with 0.5 s a guest's honest states were refused until it was
## disconnected (the person suite's network match). A forged stamp is far further off.
const LEEWAY_S: float = 60.0
## States in a row that must all read older than [constant STALE_S] before the minimum is
## taken for a bad one.
const RUN: int = 5
const STALE_S: float = 3.0

## One-way delay of the fastest path, seconds (set from ENet's round-trip statistic).
var base_latency_s: float = 0.0
## How fast the remembered minimum forgets (s of offset per s): a clock drift or a route
## change is followed within seconds.
var forget_per_s: float = 0.002

var _min_offset: float = INF
var _last_local: float = 0.0
# The states in a row read as stale so far, and the smallest offset among them.
var _stale_run: int = 0
var _stale_min: float = INF


## A state sent at remote time [param remote_s] arrived at local time [param local_s];
## returns its age, seconds, or [constant REFUSED] when its stamp does not fit.
func observe(local_s: float, remote_s: float) -> float:
	var offset: float = local_s - remote_s
	if not is_finite(offset):
		return REFUSED
	if _min_offset == INF:
		_min_offset = offset
	else:
		_min_offset += forget_per_s * maxf(local_s - _last_local, 0.0)
		if offset < _min_offset - LEEWAY_S:
			return REFUSED
		_min_offset = minf(_min_offset, offset)
	_last_local = local_s
	var age: float = base_latency_s + (offset - _min_offset)
	if age <= STALE_S:
		_stale_run = 0
		_stale_min = INF
		return age
	_stale_run += 1
	_stale_min = minf(_stale_min, offset)
	if _stale_run >= RUN:
		_min_offset = _stale_min
		_stale_run = 0
		_stale_min = INF
		return base_latency_s + (offset - _min_offset)
	return age


## Forgets the sender (a new master).
func reset() -> void:
	_min_offset = INF
	_stale_run = 0
	_stale_min = INF
