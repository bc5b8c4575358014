class_name PongNetStreamWatch
extends RefCounted
## The server's watch on its master's stream (issue 36: a master that stopped streaming, or
## streamed only states the server refused or could not use, froze the rally for everyone:
## the server follows the master's ball, and its referee saw the ball still moving). The
## stream runs dry when no state of the master's was taken for [constant DRY_S] of the time
## the master was heard and not stalling: the server then takes the ball and counts it
## against the master. A master that falls silent altogether is no dry stream: the
## heartbeat stands the computer in for it.

## How long a heard master may stream nothing the server can play, seconds: past a
## transfer's leg and its resend on a slow lossy path, and a burst of lost states.
const DRY_S: float = 2.0
## How recently the master must have been heard for its stream to be running dry, seconds:
## a few beats ([constant PongNetProtocol.HEARTBEAT_HZ]); a longer silence is an outage.
const HEARD_S: float = 0.6
## The most one frame counts, seconds: a stall of this process is not the master's.
const FRAME_MAX_S: float = 0.1

var _authority: PongNetAuthority = null
var _heartbeat: PongNetHeartbeat = null
var _reject: Callable = Callable()
var _take_ball: Callable = Callable()
var _epoch: int = -1
var _dry_s: float = 0.0


## Watches [param authority]'s master on the server, hearing peers through
## [param heartbeat]; a dry stream is refused through [param reject] (as [PongNetWeapons]
## takes it) and the ball taken by the server through [param take_ball] (master: int).
func _init(
	authority: PongNetAuthority, heartbeat: PongNetHeartbeat, reject: Callable, take_ball: Callable
) -> void:
	_authority = authority
	_heartbeat = heartbeat
	_reject = reject
	_take_ball = take_ball


## A state of the current master's stream was taken.
func fed() -> void:
	_dry_s = 0.0


## One frame of [param frame_s] on the server, at [param now_s] ([method PongNetPulse.now_s]):
## true when the master's stream ran dry in it (counted, and the ball taken).
func update(frame_s: float, now_s: float) -> bool:
	var master: int = _authority.master_peer
	if _authority.epoch != _epoch:
		_epoch = _authority.epoch
		_dry_s = 0.0
	if master == PongNetAuthority.SERVER_ID or master == 0 or _heartbeat.is_stalling(master):
		return false
	if _heartbeat.silence_s(master, now_s) > HEARD_S:
		return false
	_dry_s += clampf(frame_s, 0.0, FRAME_MAX_S)
	if _dry_s < DRY_S:
		return false
	_dry_s = -INF  # Once an epoch: the takeover starts the next.
	_reject.call(
		master, PongNetBallMessage.LABEL, "no state the server could play for %.0f s" % DRY_S
	)
	_take_ball.call(PongNetAuthority.SERVER_ID)
	return true
