class_name PongNetBallBuffer
extends RefCounted
## A follower's playout buffer for one master's ball stream (issue 24). The stream travels
## unreliable and unordered: a path that reorders (jitter larger than the send period)
## delivers most states after a newer one, and taking only the newest by arrival threw two
## thirds of them away. Here every state goes in by its sequence number, and the buffer plays
## them out in that order: a state whose predecessors have all been played goes at once; a
## gap (a state lost, or still on its way) is waited for until the state after it is
## [member delay_s] older than the fastest path would have made it, then given up. The wait
## is sized from the measured jitter: the [constant JITTER_QUANTILE] of the recent states'
## delays over the fastest one ([PongNetClock] with no base: the excess alone), at most
## [constant MAX_DELAY_S]. The wait never holds news back: when the newest state waiting
## is not where the last one played would have flown (the caller's judge: a strike, a hit),
## the gaps are given up at once, since the follower carries every state to now and a
## later state alone tells where the ball is. A state that arrives after the play has passed
## it is late; a second copy of one is a duplicate; both are counted and dropped. Across a
## burst of losses nothing is played: the servo's ball flies on by its own physics.
## Times are this machine's clock ([method Time.get_ticks_usec] in seconds) for arrivals and
## the sender's servo clock for sending times.

## What [method push] did with a state.
enum Taken { NEWEST, FILLS_GAP, DUPLICATE, LATE }

## The share of states the wait is sized to catch.
const JITTER_QUANTILE: float = 0.99
## States whose delays size the wait (at 60-125 Hz, the last 0.5-1 s).
const JITTER_WINDOW: int = 128
## The longest wait for a gap, s: a path worse than that is not waited for.
const MAX_DELAY_S: float = 0.25
## Sequence numbers remembered below the play position, to tell duplicates from late states.
const SEEN_WINDOW: int = 512


## One ball state of the stream.
class State:
	extends RefCounted
	var seq: int = 0
	## The sender's servo time when it sent it, s.
	var sent_at: float = 0.0
	var position: Vector3 = Vector3.ZERO
	var velocity: Vector3 = Vector3.ZERO
	var spin: Vector3 = Vector3.ZERO
	## When it arrived here (this machine's clock), s.
	var arrival_s: float = 0.0
	## Its age when it arrived ([PongNetLatency]), s.
	var age_s: float = 0.0

	func _init(
		p_seq: int,
		p_sent_at: float,
		p_ball: Array[Vector3],
		p_arrival_s: float,
		p_age_s: float,
	) -> void:
		seq = p_seq
		sent_at = p_sent_at
		position = p_ball[0]
		velocity = p_ball[1]
		spin = p_ball[2]
		arrival_s = p_arrival_s
		age_s = p_age_s

	## Its age at [param now_s] (this machine's clock).
	func age_at(now_s: float) -> float:
		return age_s + maxf(now_s - arrival_s, 0.0)


## The wait for a gap now, s.
var delay_s: float = 0.0
## The newest state played (null before the first of this stream).
var played: State = null
## The states the last [method advance] played, oldest first (the server judges floor claims
## by each of them, not only by the newest).
var just_played: Array[State] = []
## States taken in (neither duplicates nor late), played, late, duplicates.
var received: int = 0
var used: int = 0
var late: int = 0
var duplicates: int = 0
## Gaps given up (a state lost, late, or not waited for after a strike).
var skipped: int = 0
## Of the late states, those whose gap was given up for news (a strike), not for the wait.
var late_after_news: int = 0
## Plays that gave a gap up for news before its wait ran out.
var news: int = 0

var _pending: Dictionary[int, State] = {}
var _seen: Dictionary[int, bool] = {}
# The sequence numbers the play passed without them, each with whether news made it pass.
var _passed_for_news: Dictionary[int, bool] = {}
var _newest_seq: int = -1
var _clock: PongNetClock = PongNetClock.new()
var _excess: PackedFloat32Array = PackedFloat32Array()
var _next_excess: int = 0
# Our clock minus the sender's over the fastest path seen (PongNetClock's minimum).
var _fastest_offset: float = INF


## A new stream (a new epoch: another master, or the same one after a transfer): the
## states of the previous one are forgotten; the jitter measured so far is kept (the same
## network).
func restart() -> void:
	_pending.clear()
	_seen.clear()
	_passed_for_news.clear()
	_newest_seq = -1
	played = null
	just_played.clear()
	_clock.reset()
	_fastest_offset = INF


## Takes [param state] in; returns what became of it.
func push(state: State) -> Taken:
	if _seen.has(state.seq):
		duplicates += 1
		return Taken.DUPLICATE
	_seen[state.seq] = true
	_measure(state)  # A late state's delay is the jitter the wait is for.
	if played != null and state.seq <= played.seq:
		late += 1
		if _passed_for_news.get(state.seq, false):
			late_after_news += 1
		return Taken.LATE
	received += 1
	_pending[state.seq] = state
	if state.seq > _newest_seq:
		_newest_seq = state.seq
		return Taken.NEWEST
	return Taken.FILLS_GAP


## Plays what is due at [param now_s]; true when [member played] changed. [param agrees]
## (played: State, newest: State) -> bool says whether the newest state waiting is where
## the played one's flight leads; when it is not, no gap is waited for.
func advance(now_s: float, agrees: Callable = Callable()) -> bool:
	var moved: bool = false
	var give_up: bool = false
	just_played.clear()
	if played != null and _newest_seq > played.seq and agrees.is_valid():
		give_up = not agrees.call(played, _pending[_newest_seq])
	var for_news: bool = false
	while not _pending.is_empty():
		var next_seq: int = _pending.keys().min()
		var next: State = _pending[next_seq]
		var in_order: bool = played == null or next_seq == played.seq + 1
		var due: bool = now_s >= next.sent_at + _fastest_offset + delay_s
		if not in_order and not due and not give_up:
			break  # The gap before it may still arrive.
		if not in_order:
			skipped += 1
			for_news = for_news or (give_up and not due)
			if played != null:
				for passed: int in range(played.seq + 1, next_seq):
					_passed_for_news[passed] = give_up and not due
		_pending.erase(next_seq)
		played = next
		just_played.append(next)
		used += 1
		moved = true
	if for_news:
		news += 1
	if moved:
		_forget_below(played.seq - SEEN_WINDOW)
	return moved


## States waiting for a gap.
func waiting() -> int:
	return _pending.size()


## The counts and the wait, for the report.
func to_dict() -> Dictionary:
	return {
		"received": received,
		"used": used,
		"late": late,
		"duplicates": duplicates,
		"gaps_given_up": skipped,
		"late_after_news": late_after_news,
		"news": news,
		"delay_s": delay_s,
	}


func _measure(state: State) -> void:
	var excess: float = _clock.observe(state.arrival_s, state.sent_at)
	_fastest_offset = (state.arrival_s - state.sent_at) - excess
	if _excess.size() < JITTER_WINDOW:
		_excess.append(excess)
	else:
		_excess[_next_excess] = excess
		_next_excess = (_next_excess + 1) % JITTER_WINDOW
	delay_s = minf(PongNetSmoother.quantile(_excess, JITTER_QUANTILE), MAX_DELAY_S)


func _forget_below(seq: int) -> void:
	if _seen.size() <= 2 * SEEN_WINDOW:
		return
	for old: int in _seen.keys():
		if old < seq:
			_seen.erase(old)
	for old: int in _passed_for_news.keys():
		if old < seq:
			_passed_for_news.erase(old)
