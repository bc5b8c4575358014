class_name PongNetBudget
extends RefCounted
## How many bad messages each peer has sent, and what to do about the next one: log the
## first (one line per peer, not one per message: a peer sending thousands a second must not
## flood the log), count the rest, and give up on the peer once it reaches [member limit].
## Each counts toward the limit for a while only: one is forgiven every [member forgiven_s],
## so the rare honest refusal (a floor claim the server could not match, once in ten minutes
## on the rough path) never adds up over a long session, while a forger's burst still does.

## What to do about a bad message.
enum Verdict {
	## The peer's first: log it.
	WARN,
	## Count it, say nothing.
	COUNT,
	## The peer has reached the limit with this one: disconnect it (once).
	DISCONNECT,
}

## How much of a refusal's reason a log line keeps, characters: a floor claim's holds the
## bounces the server saw, which a rare honest refusal is diagnosed from.
const REASON_LOG_CHARS: int = 600

## Bad messages a peer may send; the one that reaches it disconnects the peer.
var limit: int = PongNetProtocol.MISBEHAVIOUR_BUDGET
## Seconds after which one counted bad message no longer weighs toward the limit.
var forgiven_s: float = PongNetProtocol.MISBEHAVIOUR_FORGIVEN_S
## The clock, seconds.
var clock: Callable = func() -> float: return Time.get_ticks_usec() / 1e6

# Every bad message each peer sent; what still weighs toward the limit, and when it was
# last weighed; the peers already given up on.
var _counts: Dictionary[int, int] = {}
var _weights: Dictionary[int, float] = {}
var _weighed_at: Dictionary[int, float] = {}
var _given_up: Dictionary[int, bool] = {}


func _init(p_limit: int = PongNetProtocol.MISBEHAVIOUR_BUDGET) -> void:
	limit = maxi(p_limit, 1)


## One more bad message from [param peer]: what to do.
func note(peer: int) -> Verdict:
	var count: int = _counts.get(peer, 0) + 1
	_counts[peer] = count
	var now: float = clock.call()
	var last: float = _weighed_at.get(peer, now)
	var weighed: float = _weights.get(peer, 0.0)
	var weight: float = maxf(weighed - maxf(now - last, 0.0) / forgiven_s, 0.0) + 1.0
	_weights[peer] = weight
	_weighed_at[peer] = now
	# Rounded: a burst's 16th bad message, a few milliseconds after the first, reaches 16.
	if roundi(weight) >= limit and not _given_up.has(peer):
		_given_up[peer] = true
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
				% [peer, what, reason.left(REASON_LOG_CHARS), limit]
			)
		Verdict.DISCONNECT:
			return (
				"PongNet: disconnecting peer %d: %d bad messages (the last: %s, %s)"
				% [peer, limit, what, reason.left(REASON_LOG_CHARS)]
			)
	return ""


## Bad messages counted from [param peer].
func count_of(peer: int) -> int:
	return _counts.get(peer, 0)


## The peer left: a new peer may get its id some day.
func forget(peer: int) -> void:
	for table: Dictionary in [_counts, _weights, _weighed_at, _given_up]:
		table.erase(peer)


## Every peer's count, for the report.
func counts() -> Dictionary[int, int]:
	return _counts.duplicate()
