class_name PongNetHurtJudge
extends RefCounted
## The server's judgement of a floor hurt a master reports: possible only when the ball's
## path, as this peer's servo ran it, bounced on the floor in the victim's territory while
## the claimant was the master (within the claim's epoch), when that bounce has not been
## charged already (one hurt per bounce), and when the victim has not lost more floor points
## lately than a ball can bounce.
## [br]The path is recorded from two sources: the servo's own floor events, and, while this
## peer follows another's ball, its state each frame, where a vertical velocity that turns
## from down to up near the floor is a bounce too (a follower's ball takes the master's
## velocity with each state it receives, so it may turn before touching the floor itself).
## A follower's copy is blended onto the master's, and may be lifted clear of the floor by
## the state after a bounce before it ever gets low (a CI match's honest claim was refused
## so): the master's own states, as they are played here, are a third source, where a turn
## counts as a bounce when the ball could have reached the floor between the two states.
## The fourth, and the surest: the bounces of the server's own simulation of the master's
## ball from the states it accepted ([PongNetBallCheck]); a forged state is refused before it
## reaches any of the others. While this peer is the master its servo's events are the whole
## truth. Times are seconds of the clock messages are aged by ([member PongNetFloorHurts.clock]).
## [br]The rate is counted by the bounces' times: one bounce per claim, however the claims
## bunch on the way.
## [br]A claim of the territory the ball was in at the claim's epoch may match a bounce up to
## [constant TERRITORY_MARGIN_M] outside it (our copy of the ball follows the master's a
## little late and blended); a claim of any other territory (the master's ball crossed and
## bounced within one frame) only a bounce strictly inside it.

enum Verdict { ACCEPT, WAIT, REFUSE }

## How far back before its arrival a claim may find its bounce: one leg and ENet's resends
## of a lost reliable packet on a slow lossy path, seconds.
const LOOKBACK_S: float = 3.0
## How long a claim waits for its bounce to appear in our path at least, seconds.
const WAIT_S: float = 1.0
## How long it may wait for the master's stream to catch up with it: a claim is reliable and
## resent, the states that show its bounce are not, and after a hiccup the claim may come
## first, seconds.
const STREAM_WAIT_S: float = LOOKBACK_S
## How far outside its epoch (as this peer applied the transfers) a bounce may lie: our copy
## of the ball and the transfers each come about a leg late, seconds.
const EPOCH_SLACK_S: float = 0.3
## Two bounces recorded closer in time than this are one (the servo's event and the turn
## of the velocity seen at the next frame); a real ball bounces again no sooner than
## 2 x 0.8 m/s / 6 m/s^2 = 0.27 s.
const SAME_BOUNCE_S: float = 0.15
## How high above the floor a ball may turn upward and still count as a bounce, besides what
## it falls in the frame: a follower's copy is blended onto the master's and may turn a
## few centimetres up, metres.
const LOW_M: float = 0.35
const TERRITORY_MARGIN_M: float = 1.0
## How far above what a ball could fall or rise between two of the master's states a turn
## may lie and still be a bounce: the states are the master's exact ball, metres.
const MASTER_LOW_M: float = 0.05
## Floor hurts a victim may take in a burst; the rate is [member rate_per_s].
const BURST: float = 2.0

var court: PongCourt = null
## Seats of the match.
var seats: int = 2
## Floor hurts per second a victim may take at most, over a burst: a ball bounces on the
## floor at least twice its slowest counted bounce speed over gravity apart.
var rate_per_s: float = 4.0

# Bounces recorded: [time, position, charged].
var _bounces: Array[Array] = []
# The last state observed: [time, position, velocity], or empty.
var _last: Array = []
# The last of the master's states played here: [time, position, velocity], or empty.
var _last_master: Array = []
# The newest time of the master's states played here (s).
var _master_newest: float = -INF
# Each victim's charged bounces' times, in order, as long as they are remembered.
var _charged_at: Array[PackedFloat64Array] = []


func _init(p_court: PongCourt, p_seats: int) -> void:
	court = p_court
	seats = p_seats
	var slowest: float = court.settings.min_bounce_speed_m_per_s
	if court.gravity > 0.0 and slowest > 0.0:
		rate_per_s = court.gravity / (2.0 * slowest)
	for seat: int in seats:
		_charged_at.append(PackedFloat64Array())


## The ball at [param t]: [param position], [param velocity] (each frame); [param master]:
## this peer simulates it for everyone (its floor events say when it bounced).
func observe(t: float, position: Vector3, velocity: Vector3, master: bool = false) -> void:
	if not _last.is_empty() and not master:
		var t0: float = _last[0]
		var p0: Vector3 = _last[1]
		var v0: Vector3 = _last[2]
		var dt: float = maxf(t - t0, 0.0)
		var low: float = LOW_M + absf(v0.y) * dt + court.ball_radius
		if v0.y < 0.0 and velocity.y > 0.0 and minf(p0.y, position.y) <= low:
			_record(t, (p0 + position) * 0.5, false)
	_last = [t, position, velocity]
	_forget_before(t - 2.0 * LOOKBACK_S)


## The master's ball was at [param position] with [param velocity] at [param t] (a state of
## its stream, played here): between two states, a ball that turned from falling to rising
## and could have touched the floor in the time between bounced.
func observe_master(t: float, position: Vector3, velocity: Vector3) -> void:
	if not _last_master.is_empty():
		var t0: float = _last_master[0]
		var p0: Vector3 = _last_master[1]
		var v0: Vector3 = _last_master[2]
		var dt: float = t - t0
		var reach: float = 0.5 * court.gravity * dt * dt + court.ball_radius + MASTER_LOW_M
		var fell: bool = p0.y <= absf(v0.y) * dt + reach
		var rose: bool = position.y <= absf(velocity.y) * dt + reach
		if dt > 0.0 and dt <= LOOKBACK_S and v0.y < 0.0 and velocity.y > 0.0 and fell and rose:
			_record(t0 + 0.5 * dt, (p0 + position) * 0.5, false)
	if _last_master.is_empty() or t > _last_master[0]:
		_last_master = [t, position, velocity]
	_master_newest = maxf(_master_newest, t)
	_forget_before(t - 2.0 * LOOKBACK_S)


## The server's own simulation of the master's ball ([PongNetBallCheck]) bounced it on the
## floor at [param t], [param position].
func observe_witness(t: float, position: Vector3) -> void:
	_record(t, position, false)


## The servo bounced the ball on the floor at [param t], [param position]; [param charged]:
## the hurt is already taken (this peer's own master's bounce).
func observe_floor(t: float, position: Vector3, charged: bool = false) -> void:
	_record(t, position, charged)


## A claim that arrived at [param claimed_at] that [param victim] lost a point to a floor
## bounce in an epoch that put the ball in [param epoch_territory] and lasted from
## [param epoch_from] to [param epoch_to] (INF: it still does), judged at [param now]:
## [verdict, why]. ACCEPT charges the bounce; WAIT: ask again later (no bounce yet, and the
## claim is younger than [constant WAIT_S]).
func judge(
	now: float,
	claimed_at: float,
	victim: int,
	epoch_territory: int,
	epoch_from: float = -INF,
	epoch_to: float = INF
) -> Array:
	if victim < 0 or victim >= seats:
		return [Verdict.REFUSE, "victim %d of %d seats" % [victim, seats]]
	var margin: float = TERRITORY_MARGIN_M if victim == epoch_territory else 0.0
	var earliest: float = maxf(claimed_at - LOOKBACK_S, epoch_from - EPOCH_SLACK_S)
	var latest: float = minf(now, epoch_to + EPOCH_SLACK_S)
	var charged_match: bool = false
	for bounce: Array in _bounces:
		var t: float = bounce[0]
		var at: Vector3 = bounce[1]
		if t < earliest or t > latest or not _near(at, victim, margin):
			continue
		if bounce[2]:
			charged_match = true
			continue
		var tokens: float = _take_token(victim, t)
		if tokens < 1.0:
			bounce[2] = true  # Claimed, and refused: no later claim takes it.
			var why: String = (
				"seat %d would lose more than %.1f floor points a second" % [victim, rate_per_s]
			)
			var story: String = _story(claimed_at, earliest, latest)
			why += " (bounce at %+.2f s, %.2f tokens); %s" % [t - claimed_at, tokens, story]
			return [Verdict.REFUSE, why]
		bounce[2] = true
		return [Verdict.ACCEPT, ""]
	var waited: float = now - claimed_at
	if waited < WAIT_S or (_master_newest < claimed_at and waited < STREAM_WAIT_S):
		return [Verdict.WAIT, ""]
	var seen: String = _story(claimed_at, earliest, latest)
	if charged_match:
		return [
			Verdict.REFUSE, "its bounce in territory %d was charged already; %s" % [victim, seen]
		]
	return [
		Verdict.REFUSE, "no floor bounce in territory %d in its epoch here; %s" % [victim, seen]
	]


## How many claims may wait at once: as many as a ball can bounce in the longest wait.
func max_waiting() -> int:
	return ceili(rate_per_s * STREAM_WAIT_S + BURST)


## Bounces recorded and still remembered, [time, position, charged] each.
func bounces() -> Array[Array]:
	return _bounces


# What this peer saw around a refused claim that arrived at [param claimed_at], which looked
# from [param earliest] to [param latest]: times are relative to its arrival (a rare honest
# refusal is diagnosed from this alone).
func _story(claimed_at: float, earliest: float, latest: float) -> String:
	var seen: PackedStringArray = PackedStringArray()
	for bounce: Array in _bounces:
		var t: float = bounce[0]
		if absf(t - claimed_at) <= 2.0 * LOOKBACK_S:
			var at: Vector3 = bounce[1]
			var mark: String = " charged" if bounce[2] else ""
			seen.append(
				(
					"%+.2f s at (%.2f, %.2f) territory %d%s"
					% [t - claimed_at, at.x, at.z, PongCourt.territory_of(at, seats), mark]
				)
			)
	return (
		"looked from %+.2f to %+.2f s, master's states to %+.2f s; bounces: %s"
		% [
			earliest - claimed_at,
			latest - claimed_at,
			_master_newest - claimed_at,
			", ".join(seen) if not seen.is_empty() else "none"
		]
	)


func _near(point: Vector3, territory: int, margin: float) -> bool:
	return PongNetProtocol.near_territory(point, territory, seats, margin)


func _record(t: float, position: Vector3, charged: bool) -> void:
	for bounce: Array in _bounces:
		var earlier: float = bounce[0]
		if absf(earlier - t) < SAME_BOUNCE_S:
			bounce[2] = bounce[2] or charged
			return
	_bounces.append([t, position, charged])


func _forget_before(t: float) -> void:
	while not _bounces.is_empty() and _bounces[0][0] < t:
		_bounces.pop_front()


# Takes a token from [param victim]'s bucket for a bounce at [param at] when the bucket, filled
# by the bounces' own times in their order, holds one at every charged bounce with it; returns
# the fewest tokens it held at one. By the bounces' times, not the claims': a hiccup holds
# claims back and they arrive together, and a claim may come before an earlier bounce's (both
# were refused so).
func _take_token(victim: int, at: float) -> float:
	var times: PackedFloat64Array = _charged_at[victim].duplicate()
	times.append(at)
	times.sort()
	var tokens: float = BURST
	var fewest: float = INF
	for i: int in times.size():
		if i > 0:
			tokens = minf(BURST, tokens + (times[i] - times[i - 1]) * rate_per_s)
		fewest = minf(fewest, tokens)
		tokens -= 1.0
	if fewest >= 1.0:
		var keep_from: int = times.bsearch(times[-1] - 2.0 * LOOKBACK_S)
		_charged_at[victim] = times.slice(keep_from)
	return fewest
