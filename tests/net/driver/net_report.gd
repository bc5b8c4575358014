extends RefCounted
## What one peer saw of a networked match, for the tests and the benchmark (written as JSON
## at exit by the test driver, net_peer.gd), gathered from the signals of the product's
## nodes ([method watch], [method begin]) and a sample of the ball each frame
## ([method sample]). Wall times are this machine's Unix clock: the protocol never uses them,
## they only let a test line up peers running on one machine.

## Seconds between trajectory samples.
const SAMPLE_INTERVAL_S: float = 0.01
const MAX_REASONS: int = 20

var peer: int = 0
var winner: int = -1
## Ball states sent (as master), taken, stale ones dropped, poses taken.
var sent: int = 0
var states: int = 0
## States taken, per sender.
var states_from: Dictionary[int, int] = {}
var late: int = 0
var poses: int = 0
## Age estimate of each state taken, seconds.
var ages: PackedFloat32Array = PackedFloat32Array()
## The most a network correction moved the servo's ball in one tick, metres.
var correction_step_max_m: float = 0.0
## |target - local| at each transfer, metres.
var handoff_corrections: PackedFloat32Array = PackedFloat32Array()
## [epoch, player, cause] of each health loss applied.
var hurts: Array[Array] = []
## Messages dropped by the checks, by kind.
var refused: Dictionary[String, int] = {}
## The first [constant MAX_REASONS] of them: [peer, kind, why] (a flaky refusal is read here).
var reasons: Array[Array] = []
## Extra entries (peer losses, contact profiles, ...).
var extra: Dictionary = {}

var _play: PongNetPlay = null
var _transfers: Array[Dictionary] = []
var _samples: Array[PackedFloat64Array] = []
var _intervals: Array[PackedFloat64Array] = []
var _master_since: float = -1.0
var _last_sample: float = -INF
var _started: float = 0.0


## Follows [param play] and its session for the whole session.
func watch(play: PongNetPlay) -> void:
	_play = play
	play.session.bad_message.connect(_on_bad_message)
	play.ball_state_sent.connect(func() -> void: sent += 1)
	play.ball_state_taken.connect(_on_state_taken)
	play.ball_state_late.connect(func() -> void: late += 1)
	play.transferred.connect(_on_transferred)
	var pulse: PongNetPulse = play.session.pulse
	pulse.peer_absent.connect(_on_silence.bind("absent"))
	pulse.peer_back.connect(_on_silence.bind("back"))
	play.seats.taken_over.connect(_on_seats_taken_over)
	play.seats.given_back.connect(_on_seats_given_back)
	play.finished.connect(func(p_winner: int) -> void: winner = p_winner)


## A match began (after [method PongNetPlay.begin]): its poses, floor hurts and weapons.
## [param rejoined]: the same match again on a new connection, whose start carried the
## health: the hurts are counted from there (the weapons' lists are the new match's).
func begin(play: PongNetPlay, rejoined: bool = false) -> void:
	if rejoined:
		hurts.clear()
	peer = play.authority.my_id
	_started = now()
	play.poses.pose_taken.connect(func(_seat: int) -> void: poses += 1)
	play.floor_hurts.hurt_applied.connect(
		func(epoch: int, victim: int) -> void: hurts.append([epoch, victim, "floor"])
	)
	play.floor_hurts.claimed.connect(_on_claimed)
	var weapons: PongNetWeapons = play.weapons
	extra["weapons"] = {
		"shots": weapons.shots, "mines": weapons.mines_placed, "hurts": weapons.hurts
	}


# A refused claim is diagnosed from the claimant's side too: what its servo saw, and when.
func _on_claimed(epoch: int, event: PongEvent) -> void:
	var claims: Array = extra.get_or_add("claims", [])
	var at: Vector3 = event.position
	claims.append([now(), epoch, event.territory, at.x, at.y, at.z, event.speed, event.time_s])


static func now() -> float:
	return Time.get_unix_time_from_system()


func _on_bad_message(sender: int, what: String, reason: String) -> void:
	refused[what] = refused.get(what, 0) + 1
	if reasons.size() < MAX_REASONS:
		reasons.append([sender, what, reason])


func _on_state_taken(sender: int, age_s: float) -> void:
	states += 1
	states_from[sender] = states_from.get(sender, 0) + 1
	ages.append(age_s)


func _on_transferred(entry: Dictionary, correction_m: float) -> void:
	var copy: Dictionary = entry.duplicate()
	copy["wall_s"] = now()
	_transfers.append(copy)
	handoff_corrections.append(correction_m)


func _on_seats_taken_over(left_peer: int, seats: PackedInt32Array) -> void:
	var left: Array = extra.get_or_add("peers_left", [])
	left.append({"peer": left_peer, "seats": Array(seats), "wall_s": now()})


# A peer was found absent, or back, after [param silence_s]: under [param what].
func _on_silence(silent_peer: int, silence_s: float, what: String) -> void:
	var entries: Array = extra.get_or_add(what, [])
	entries.append({"peer": silent_peer, "silence_s": silence_s, "wall_s": now()})


func _on_seats_given_back(back_peer: int, seats: PackedInt32Array) -> void:
	var back: Array = extra.get_or_add("seats_back", [])
	var health: Array[int] = []
	for seat: int in _play.authority.owners.size():
		health.append(_play.match_node.rules.get_health(seat))
	back.append({"peer": back_peer, "seats": Array(seats), "wall_s": now(), "health": health})


## The ball in this peer's servo [param snapshot]; [param master]: whether this peer
## simulates it for everyone.
func sample(snapshot: PongState, master: bool) -> void:
	correction_step_max_m = maxf(correction_step_max_m, snapshot.ball_correction_step_max)
	var position: Vector3 = snapshot.ball_position
	var sim_s: float = snapshot.time_s
	var t: float = now()
	if master and _master_since < 0.0:
		_master_since = t
	elif not master and _master_since >= 0.0:
		_intervals.append(PackedFloat64Array([_master_since, t]))
		_master_since = -1.0
	if t - _last_sample >= SAMPLE_INTERVAL_S:
		_last_sample = t
		_samples.append(PackedFloat64Array([t, sim_s, position.x, position.y, position.z]))


## Everything as a JSON-ready Dictionary: the play's ball gives the correction sizes and the
## stream's counts, its authority the refusals it counted.
func to_dict() -> Dictionary:
	var smoother: PongNetSmoother = _play.ball.smoother
	var authority: PongNetAuthority = _play.authority
	extra["ball_stream"] = _play.ball.to_dict()
	if _play.ball_check != null:
		extra["ball_check"] = _play.ball_check.to_dict()
	var intervals: Array = _intervals.duplicate()
	if _master_since >= 0.0:
		intervals.append(PackedFloat64Array([_master_since, now()]))
	var all_refused: Dictionary = refused.duplicate()
	if authority != null:
		for key: String in authority.refusals:
			all_refused["authority: " + key] = authority.refusals[key]
	return {
		"peer": peer,
		"seconds": now() - _started if _started > 0.0 else 0.0,
		"winner": winner,
		"sent": sent,
		"states": states,
		"states_from": states_from,
		"forwarded": _play.session.router.forwarded,
		"late": late,
		"poses": poses,
		"age_p50_s": PongNetSmoother.quantile(ages, 0.5),
		"age_p99_s": PongNetSmoother.quantile(ages, 0.99),
		"corrections":
		{
			"count": smoother.sizes.size(),
			"snaps": smoother.snaps,
			"p50_m": PongNetSmoother.quantile(smoother.sizes, 0.5),
			"p99_m": PongNetSmoother.quantile(smoother.sizes, 0.99),
			"max_m": PongNetSmoother.quantile(smoother.sizes, 1.0),
		},
		"handoff_corrections_m": Array(handoff_corrections),
		"correction_step_max_m": correction_step_max_m,
		"transfers": _transfers,
		"master_intervals": intervals,
		"samples": _samples,
		"hurts": hurts,
		"refused": all_refused,
		"refusal_reasons": reasons,
		"extra": extra,
	}
