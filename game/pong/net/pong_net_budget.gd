class_name PongNetBudget
extends RefCounted
## How many bad messages each peer has sent, and what to do about the next one: log the
## first (one line per peer, not one per message: a peer sending thousands a second must not
## flood the log), count the rest, and give up on the peer once it reaches [member limit].

## What to do about a bad message.
enum Verdict {
	## The peer's first: log it.
	WARN,
	## Count it, say nothing.
	COUNT,
	## The peer has reached the limit with this one: disconnect it (once).
	DISCONNECT,
}

## Bad messages a peer may send; the one that reaches it disconnects the peer.
var limit: int = PongNetProtocol.MISBEHAVIOUR_BUDGET

var _counts: Dictionary[int, int] = {}


func _init(p_limit: int = PongNetProtocol.MISBEHAVIOUR_BUDGET) -> void:
	limit = maxi(p_limit, 1)


## One more bad message from [param peer]: what to do.
func note(peer: int) -> Verdict:
	var count: int = _counts.get(peer, 0) + 1
	_counts[peer] = count
	if count == limit:
		return Verdict.DISCONNECT
	return Verdict.WARN if count == 1 else Verdict.COUNT


## The log line for [param verdict] on [param peer]'s bad [param what] ([param reason]), ""
## when there is nothing to say.
func log_line(verdict: Verdict, peer: int, what: String, reason: String) -> String:
	match verdict:
		Verdict.WARN:
			return (
				(
					"PongNet: peer %d sent a bad %s (%s); its next bad messages are counted, "
					+ "not logged, and %d disconnect it"
				)
				% [peer, what, reason.left(200), limit]
			)
		Verdict.DISCONNECT:
			return (
				"PongNet: disconnecting peer %d: %d bad messages (the last: %s, %s)"
				% [peer, limit, what, reason.left(200)]
			)
	return ""


## Bad messages counted from [param peer].
func count_of(peer: int) -> int:
	return _counts.get(peer, 0)


## The peer left: a new peer may get its id some day.
func forget(peer: int) -> void:
	_counts.erase(peer)


## Every peer's count, for the report.
func counts() -> Dictionary[int, int]:
	return _counts.duplicate()
