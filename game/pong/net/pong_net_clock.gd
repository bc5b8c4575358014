class_name PongNetClock
extends RefCounted
## How old a received stream state is, without synchronised clocks. Each state carries
## the sender's servo time; the difference to our receive time is a constant offset plus
## the path's delay. The smallest difference seen recently stands for the fastest path;
## a state that took longer (jitter, queueing) is older by the excess. The fastest path's
## own delay comes from ENet's round trip ([member base_latency_s], half of it per leg).

## One-way delay of the fastest path, seconds (set from ENet's round-trip statistic).
var base_latency_s: float = 0.0
## How fast the remembered minimum forgets (s of offset per s): a clock drift or a route
## change is followed within seconds.
var forget_per_s: float = 0.002

var _min_offset: float = INF
var _last_local: float = 0.0


## A state sent at remote time [param remote_s] arrived at local time [param local_s];
## returns its age, seconds.
func observe(local_s: float, remote_s: float) -> float:
	var offset: float = local_s - remote_s
	if _min_offset == INF:
		_min_offset = offset
	else:
		_min_offset += forget_per_s * maxf(local_s - _last_local, 0.0)
		_min_offset = minf(_min_offset, offset)
	_last_local = local_s
	return base_latency_s + (offset - _min_offset)


## Forgets the sender (a new master).
func reset() -> void:
	_min_offset = INF
