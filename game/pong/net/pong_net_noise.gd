class_name PongNetNoise
extends RefCounted
## Well-formed messages that are refused as stale (a state of an old epoch, a hand-off
## request a newer transfer overtook): an honest peer sends a few after each transfer, so
## one alone is no bad message, but a stream of them is. Counts them per peer and second and
## says when a peer's reach [member limit_per_s] in a second (once that second): the caller
## counts that as one bad message. (A master's stream of stale states, 21,392 in 7 s, had
## cost its sender nothing.)

var limit_per_s: int = 0

var _second: int = -1
var _counts: Dictionary[int, int] = {}


func _init(p_limit_per_s: int) -> void:
	limit_per_s = p_limit_per_s


## One refused message of [param peer] at [param now_s]; true when it is its
## [member limit_per_s]th this second.
func note(peer: int, now_s: float) -> bool:
	var second: int = floori(now_s)
	if second != _second:
		_second = second
		_counts.clear()
	var count: int = _counts.get(peer, 0) + 1
	_counts[peer] = count
	return count == limit_per_s
