class_name PongNetHeartbeat
extends RefCounted
## When this peer last heard each connected peer's heartbeat, and when to send its own
## ([constant PongNetProtocol.HEARTBEAT_HZ]). A peer silent past its limit is overdue; one
## whose seat is kept through the silence stays watched as absent until it is heard again
## (it is back) or the grace runs out ([method given_up]). Times are seconds of one monotonic
## clock the caller passes in, so the rules can be tested without waiting.

## Frames of stall notices after [method settle].
const SETTLE_FRAMES: int = 20
## A longer gap between two frames is this process's own stall ([method frame]), seconds.
const LOCAL_STALL_S: float = 0.25

var _last_heard: Dictionary[int, float] = {}
var _next_beat_s: float = -INF
var _last_frame_s: float = INF
# Peers that said they are about to stall, until their next beat.
var _stalling: Dictionary[int, bool] = {}
# Frames left in which this peer sends stall notices instead of beats (see settle).
var _settle_frames_left: int = 0
# Peers watched and not yet heard ([constant PongNetProtocol.FIRST_BEAT_TIMEOUT_S]).
var _unheard: Dictionary[int, bool] = {}
# Peers overdue and still watched (their seats kept).
var _absent: Dictionary[int, bool] = {}
# Absent peers heard again since the last call of returned(), each [peer, silence].
var _returned: Array[Array] = []


## Starts watching [param peer] (just connected): it counts as heard at [param now_s], and
## has until [constant PongNetProtocol.FIRST_BEAT_TIMEOUT_S] for its first beat.
func watch(peer: int, now_s: float) -> void:
	_last_heard[peer] = now_s
	_unheard[peer] = true


## Stops watching [param peer] (gone).
func forget(peer: int) -> void:
	_last_heard.erase(peer)
	_stalling.erase(peer)
	_unheard.erase(peer)
	_absent.erase(peer)


## Forgets everyone (the session closed).
func clear() -> void:
	_last_heard.clear()
	_stalling.clear()
	_unheard.clear()
	_absent.clear()
	_returned.clear()
	_next_beat_s = -INF
	_settle_frames_left = 0
	_last_frame_s = INF


## A beat of [param peer] came at [param now_s]; ignored for a peer not watched (one that
## has not passed the version check, or was dropped).
func heard(peer: int, now_s: float) -> void:
	if _last_heard.has(peer):
		if _absent.has(peer):
			_returned.append([peer, now_s - _last_heard[peer]])
			_absent.erase(peer)
		_last_heard[peer] = maxf(_last_heard[peer], now_s)
		_stalling.erase(peer)
		_unheard.erase(peer)


## [param peer] said it is about to stall (it loads a match); it counts as heard at
## [param now_s], and [method is_stalling] until its next beat.
func stalls(peer: int, now_s: float) -> void:
	if _last_heard.has(peer):
		_last_heard[peer] = maxf(_last_heard[peer], now_s)
		_stalling[peer] = true
		_unheard.erase(peer)


## Whether [param peer] said it stalls and has not beaten since.
func is_stalling(peer: int) -> bool:
	return _stalling.has(peer)


## This peer has announced a stall (it loads a match's court; its partners then allow it
## [constant PongNetProtocol.LOAD_STALL_TIMEOUT_S]): for the next [constant SETTLE_FRAMES]
## frames it repeats the notice instead of beating. The court's first
## frames compile its shaders and can each take over a second on a slow machine; a beat
## between them would end the partners' patience with this peer.
func settle() -> void:
	_settle_frames_left = SETTLE_FRAMES


## Whether this frame sends a stall notice rather than a beat (counts the frame).
func settling() -> bool:
	if _settle_frames_left <= 0:
		return false
	_settle_frames_left -= 1
	return true


## Whether our beats are due at [param now_s]; when they are, the next ones are scheduled
## (after a stall, one round goes out, not the ones missed).
func due(now_s: float) -> bool:
	if now_s < _next_beat_s:
		return false
	var interval: float = 1.0 / PongNetProtocol.HEARTBEAT_HZ
	_next_beat_s += interval
	if _next_beat_s <= now_s:
		_next_beat_s = now_s + interval
	return true


## Seconds since [param peer] was last heard (0 for a peer not watched).
func silence_s(peer: int, now_s: float) -> float:
	return now_s - _last_heard[peer] if _last_heard.has(peer) else 0.0


## The peers watched.
func peers() -> Array[int]:
	return _last_heard.keys()


## A frame of this process at [param now_s]; true when a longer gap than
## [constant LOCAL_STALL_S] since the last one makes it this process's own stall (a court
## loading, a hitch): what the peers sent meanwhile may wait unread, and must be read before
## anyone is judged silent (a host whose court took 5 s to load found its client 5 s silent
## in that very frame). Excusing the gap instead hid a dead server for 9 s from a game that
## drew 3 frames a second.
func frame(now_s: float) -> bool:
	var gap: float = now_s - _last_frame_s
	_last_frame_s = now_s
	return gap > LOCAL_STALL_S and is_finite(gap)


## The peers silent at [param now_s] for longer than their limit
## ([param limit_of]: Callable(peer) -> seconds, once a peer has been heard), each
## [peer, silence, limit]. Those heard once for which [param keeps] (Callable(peer) -> bool)
## holds stay
## watched as absent (reported once); the others are no longer watched.
func overdue(now_s: float, limit_of: Callable, keeps: Callable = Callable()) -> Array[Array]:
	var dead: Array[Array] = []
	for peer: int in _last_heard.keys():
		if _absent.has(peer):
			continue
		var silence: float = now_s - _last_heard[peer]
		var limit: float = (
			PongNetProtocol.FIRST_BEAT_TIMEOUT_S if _unheard.has(peer) else limit_of.call(peer)
		)
		if silence > limit:
			if not _unheard.has(peer) and keeps.is_valid() and keeps.call(peer):
				_absent[peer] = true
			else:
				forget(peer)
			dead.append([peer, silence, limit])
	return dead


## Whether [param peer] is absent: overdue, its seat kept, not heard since.
func is_absent(peer: int) -> bool:
	return _absent.has(peer)


## The absent peers silent at [param now_s] for longer than [param grace_s], each
## [peer, silence]; they are no longer watched.
func given_up(now_s: float, grace_s: float) -> Array[Array]:
	var gone: Array[Array] = []
	for peer: int in _absent.keys():
		var silence: float = now_s - _last_heard[peer]
		if silence > grace_s:
			forget(peer)
			gone.append([peer, silence])
	return gone


## The absent peers heard again since the last call, each [peer, silence it ended].
func returned() -> Array[Array]:
	var back: Array[Array] = _returned
	_returned = []
	return back
