class_name PongNetBallCheck
extends RefCounted
## The server's check of its master's ball (issue 36: a master that streamed a forged ball
## bouncing in the opponent's territory had every floor claim accepted). Each state of the
## master's stream is checked against the server's own simulation of the ball, in the servo's
## Pong renderer ([method PongServo.check_ball]: free flight and court bounces from the
## ball's current flight, a paddle's touch only where the server had a paddle near the
## ball): a state it cannot reach is refused and counted against the master, and is never
## played here. The floor bounces of that simulation are the ones a floor claim may match.
## A ball the master's states put in another territory is handed over by the server when
## the master has not asked for the hand-off itself within [constant LEFT_BEHIND_S].
## Times are seconds of the clock messages are aged by ([member PongNetFloorHurts.clock]).

## What became of a state.
enum Outcome { PLAY, REFUSE, DROP }


## A hand-off the server owes: the ball as the master's newest state had it.
class Owed:
	extends RefCounted
	var territory: int = 0
	var position: Vector3 = Vector3.ZERO
	var velocity: Vector3 = Vector3.ZERO
	var spin: Vector3 = Vector3.ZERO
	## The state's age now, ms.
	var age_ms: int = 0


## How long the master's states may show the ball in another territory before the server
## hands it over: an honest master asks at once, and its request crosses one leg, resent by
## ENet through the rough path's losses, s.
const LEFT_BEHIND_S: float = 1.0

## Why the last state was refused.
var reason: String = ""
## Verdicts by name ([constant PongServoFacts.WITNESS_VERDICT_NAMES]), for the report.
var verdicts: Dictionary[String, int] = {}
## The farthest a played state lay from the free flight it was checked against, m.
var worst_miss_m: float = 0.0

var _court: PongCourt = null
var _judge: PongNetHurtJudge = null
var _authority: PongNetAuthority = null
# The newest state played (null: none this epoch), when it arrived (s) and its age then.
var _newest: PongNetBallMessage = null
var _newest_arrival: float = 0.0
var _newest_age_s: float = 0.0
# Since when (s) the played states have shown the ball outside the master's
# territory (INF: they do not).
var _out_since: float = INF
# The ball the server handed over at the epoch's start ([position, velocity, spin]) and
# when (s); empty once it anchored the epoch's flight.
var _handed: Array[Vector3] = []
var _handed_at: float = 0.0
var _new_match: bool = true


func _init(court: PongCourt, judge: PongNetHurtJudge, authority: PongNetAuthority) -> void:
	_court = court
	_judge = judge
	_authority = authority


## A pose [param sender] sent: the master's own paddle, stamped with the clock its ball
## states carry, places a touch on the ball's flight exactly.
func note_pose(sender: int, pose: PongNetPoseMessage) -> void:
	if sender != _authority.master_peer or _authority.epoch < 1:
		return
	var witnessed: PongWitnessPose = PongWitnessPose.new()
	witnessed.epoch = _authority.epoch
	witnessed.time_s = pose.time_s
	witnessed.center = pose.avatar + pose.offset
	PongServo.shared().note_master_pose(witnessed)


## Checks [param state] of the master's stream, [param age_s] old on arrival at
## [param now] (s): PLAY it, REFUSE it ([member reason] says why) or DROP it
## (older than every state of its epoch here: not judged).
func admit(state: PongNetBallMessage, age_s: float, now: float) -> Outcome:
	var age: float = clampf(age_s, 0.0, 10.0)
	if not _handed.is_empty():
		# The epoch's flight starts from the ball handed over, placed in the master's time
		# by this state's age; the new master's first state is checked from there.
		var since: float = maxf((now - age) - _handed_at, 0.001)
		_check(state.epoch, state.time_s - since, _handed, age + since)
		_handed = []
	var ball: Array[Vector3] = [state.position, state.velocity, state.spin]
	var verdict: PongWitnessVerdict = _check(state.epoch, state.time_s, ball, age)
	if verdict == null:
		return Outcome.PLAY  # No extension: nothing to check with.
	var name: String = PongServoFacts.WITNESS_VERDICT_NAMES[verdict.verdict]
	verdicts[name] = verdicts.get(name, 0) + 1
	match verdict.verdict:
		PongServoFacts.WitnessVerdict.UNREACHABLE:
			reason = (
				"a ball its flight cannot reach: %.2f m, %.1f m/s from where it flies, no paddle near"
				% [verdict.miss_m, verdict.miss_m_per_s]
			)
			return Outcome.REFUSE
		PongServoFacts.WitnessVerdict.OLD:
			return Outcome.DROP
	if verdict.verdict == PongServoFacts.WitnessVerdict.FLOWN:
		worst_miss_m = maxf(worst_miss_m, verdict.miss_m)
	for bounce: PongWitnessBounce in verdict.bounces:
		_judge.observe_witness(now - bounce.ago_s, bounce.position)
	if _newest == null or state.time_s > _newest.time_s:
		_newest = state
		_newest_arrival = now
		_newest_age_s = age_s
	return Outcome.PLAY


## A new epoch, its ball [param handed] ([position, velocity, spin]) as the server handed
## it over at [param now] (s): nothing of the old master's stream counts toward
## a hand-off, and the new master's states are checked from that ball.
func restart(handed: Array[Vector3], now: float) -> void:
	_newest = null
	_out_since = INF
	_handed = handed.duplicate()
	_handed_at = now


# The server's simulation's verdict on [param ball] of [param epoch] at the master's
# [param time_s], [param age_s] old here (null without the extension).
func _check(epoch: int, time_s: float, ball: Array[Vector3], age_s: float) -> PongWitnessVerdict:
	var check: PongWitnessCheck = PongWitnessCheck.new()
	check.epoch = epoch
	check.time_s = maxf(time_s, 0.0)
	check.position = ball[0]
	check.velocity = ball[1]
	check.spin = ball[2]
	check.age_s = clampf(age_s, 0.0, 10.0)
	check.new_match = _new_match
	_new_match = false
	check.territory = clampi(_authority.territory, 0, 3)
	return PongServo.shared().check_ball(check)


## Server: the hand-off it owes (see [method left_behind]) while a client is master, or null.
func owed_hand_off(authority: PongNetAuthority, now: float) -> Owed:
	if authority.is_master() or authority.master_peer == 0:
		return null
	return left_behind(authority.territory, now)


## Server, following a master of [param territory]: the hand-off the server owes, when the
## master's states have shown the ball in another territory for [constant LEFT_BEHIND_S]
## by [param now] (s), or null.
func left_behind(territory: int, now: float) -> Owed:
	if _newest == null:
		return null
	var there: int = _court.territory_at(_newest.position)
	if there == territory:
		_out_since = INF
		return null
	_out_since = minf(_out_since, _newest_arrival)
	if now - _out_since < LEFT_BEHIND_S:
		return null
	var owed: Owed = Owed.new()
	owed.territory = there
	owed.position = _newest.position
	owed.velocity = _newest.velocity
	owed.spin = _newest.spin
	owed.age_ms = roundi((now - _newest_arrival + _newest_age_s) * 1000.0)
	return owed


## The verdicts and the worst miss, for the report.
func to_dict() -> Dictionary:
	return {"verdicts": verdicts, "worst_miss_m": worst_miss_m}
