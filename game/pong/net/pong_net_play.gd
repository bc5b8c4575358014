class_name PongNetPlay
extends PongNetWire
## One networked match on this peer: the private haptic space. Every peer runs the servo
## and simulates the ball; the owner of the territory the ball is in is its master
## ([PongNetAuthority]): it sends the ball state on every new servo state (>= 60 Hz,
## unreliable, its own channel) and its contact with the ball stays in its own
## servo at 1 kHz whatever the latency (contact is never sent). Followers play the
## received states out in order from a jitter buffer, carry each forward to now, and the
## servo blends their ball onto it ([PongNetBall]). Each
## peer sends the poses of the paddles it drives; other peers' paddles are kinematic
## inputs of the local servo ([PongNetPoses], [PongNetRemotePlayer]). Health changes come
## as reliable messages: floor bounces from the server, which judges the master's claims
## against the ball's path ([PongNetFloorHurts]), weapon hurts from the victim's peer
## ([PongNetWeapons]). Every received message is checked ([PongNetProtocol]); a bad one is
## dropped and counted against its sender ([method PongNetSession.misbehaved]). Messages are
## aged by [PongNetLatency].
##
## RPC surface: the same methods at the same path on every peer (/root/PongNet/Play).
## The play node lives as long as the session (RPCs may arrive before or after a match).

## Health changed on every peer the same way; the match is over on every peer.
signal finished(winner: int)
## The server changed who owns which seat (a player left).
signal owners_changed

## Servo seconds after a transfer during which the servo's state is not trusted: the
## set_ball of the transfer reaches the servo a tick later (no hand-off request, no
## stream from a state the transfer has not replaced yet).
const SETTLE_S: float = 0.02
## Seconds of simulation the game steps per chunk in stepped mode.
const CHUNK_S: float = PongMatch.STEP_CHUNK_S
## The streams send on each new servo state, at most this often (a headless or fast
## machine renders hundreds of frames a second), Hz.
const MAX_STREAM_HZ: float = 125.0

var authority: PongNetAuthority = null
var match_node: PongMatch = null
## Our ball in the servo, as the network moves it.
var ball: PongNetBall = PongNetBall.new()
var report: PongNetReport = PongNetReport.new()
## Seats this peer drives (its player's, or on the server the computer's).
var local_seats: PackedInt32Array = PackedInt32Array()
## Stepped: the servo is stepped here, paced by the wall clock (headless peers).
var stepped: bool = false
## A second of stepping may not take more than this many chunks (a stalled process does
## not try to catch up for ever).
var max_chunks_per_frame: int = 10
## Server: where a serve to a receiver aims, Callable(receiver, avatar) -> Vector3 (a test
## script's; unset: at the receiver's avatar).
var serve_aim: Callable = Callable()

var _predictor: PongPredictor = null
# Kept for the session: the servo clocks' offsets and the legs peers reported.
var _latency: PongNetLatency = null
var _seq: int = 0
var _last_sent_time: float = -INF
var _last_pose_time: float = -INF
var _settle_until: float = 0.0
var _owe_s: float = 0.0
var _last_now: float = 0.0
var _running: bool = false
## The ball's velocity as its master last streamed it (Vector3.INF: none since the last
## transfer): what the server judges a stall by while it follows.
var _master_velocity: Vector3 = Vector3.INF


## Starts following [param p_match] (already started) with [param p_authority].
func begin(p_match: PongMatch, p_authority: PongNetAuthority, seats: PackedInt32Array) -> void:
	match_node = p_match
	authority = p_authority
	local_seats = seats
	ball.court = match_node.court
	_predictor = PongPredictor.new(match_node.court)
	match_node.event_seen.connect(_on_event)
	match_node.event_seen.connect(_on_ball_touch)
	match_node.match_over.connect(_on_match_over)
	report.begin(authority.my_id)
	if _latency == null:
		_latency = PongNetLatency.new(session)
	weapons = PongNetWeapons.new(self, match_node, authority, _reject, _age_of)
	poses = PongNetPoses.new(self, match_node, authority, report, _reject, _age_of)
	floor_hurts = PongNetFloorHurts.new(self, match_node, authority, report, _reject)
	report.extra["weapons"] = weapons.to_dict()
	report.extra["ball_stream"] = ball.to_dict()
	# The servo's clock may have started over with the match.
	_last_sent_time = -INF
	_last_pose_time = -INF
	ball.restart()
	_master_velocity = Vector3.INF
	_running = true


## Stops (the match is over, or the peer leaves).
func end() -> void:
	_running = false
	if weapons != null:
		weapons.expire_pending(true)
	weapons = null
	poses = null
	floor_hurts = null


func is_running() -> bool:
	return _running


## One frame: step the servo (stepped mode), serve (server), hand off, stream, correct.
func frame(delta: float) -> void:
	if not _running:
		return
	weapons.expire_pending()
	if stepped:
		_owe_s += delta
		var chunks: int = mini(floori(_owe_s / CHUNK_S), max_chunks_per_frame)
		_owe_s = minf(_owe_s - chunks * CHUNK_S, CHUNK_S)
		if chunks > 0:
			match_node.run_until(func() -> bool: return false, (chunks - 0.5) * CHUNK_S)
	# After the stepping: the target is carried to now, where the servo is.
	if not authority.is_master() and ball.follow(PongNetBall.clock_s(), _predictor, _gravity()):
		# Only the newest state played becomes a command to the servo (whose queue holds 64).
		_master_velocity = ball.buffer.played.velocity
		report.extra["ball_stream"] = ball.to_dict()
	var snapshot: PongState = match_node.snapshot
	var sim_dt: float = match_node.now - _last_now
	_last_now = match_node.now
	if authority.my_id == PongNetAuthority.SERVER_ID:
		_referee(sim_dt)
	if authority.is_master() and snapshot.time_s > _settle_until:
		if snapshot.territory != authority.territory:
			_hand_off(snapshot)
	var settled: bool = snapshot.time_s > _settle_until
	var due: bool = snapshot.time_s - _last_sent_time >= 1.0 / MAX_STREAM_HZ
	if authority.is_master() and settled and due:
		_last_sent_time = snapshot.time_s
		_seq += 1
		report.sent += 1
		send_all(
			&"_ball",
			[authority.epoch, _seq, snapshot.time_s] + _ball_of(snapshot) + [_latency.my_leg_ms()]
		)
	if snapshot.time_s - _last_pose_time >= 1.0 / MAX_STREAM_HZ:
		_last_pose_time = snapshot.time_s
		poses.send(snapshot, local_seats, _latency.my_leg_ms())
	report.sample(snapshot, authority.is_master())
	floor_hurts.observe(snapshot)


func _referee(sim_dt: float) -> void:
	var rules: PongRules = match_node.rules
	var velocity: Vector3 = match_node.snapshot.ball_velocity
	if not authority.is_master() and _master_velocity != Vector3.INF:
		# A follower's ball falls between the master's states and is lifted back by each
		# correction: at rest on the floor it never looked still here, and a ball that
		# had rolled dead 150 ms away went unserved for five seconds.
		velocity = _master_velocity
	if rules.is_over() or not match_node.referee.update(sim_dt, velocity):
		return
	var receiver: int = match_node.next_receiver()
	var aim: Vector3 = match_node.avatar_of(receiver)
	if serve_aim.is_valid():
		aim = serve_aim.call(receiver, aim)
	var serve: PongReferee.Serve = match_node.referee.make_serve(
		match_node.court, aim, match_node.beginner
	)
	var territory: int = match_node.court.territory_at(serve.position)
	issue(
		PongNetProtocol.TRANSFER_SERVE, territory, serve.position, serve.velocity, Vector3.ZERO, 0
	)


## Server: [param peer] left. Its seats go to the computer (driven here), and a ball it was
## master of, or one whose hand-off is pending while the server owns the territory, is taken
## over at once from the server's own ball, so the ball is never left without a master.
func take_over(peer: int) -> void:
	var was_master: bool = authority.master_peer == peer
	var freed: PackedInt32Array = authority.release_peer(peer)
	var left: Array = report.extra.get_or_add("peers_left", [])
	left.append({"peer": peer, "seats": Array(freed), "wall_s": PongNetReport.now()})
	send_all(&"_owners", [authority.owners])
	owners_changed.emit()
	var pending: bool = authority.master_peer == 0 or not authority.is_master()
	var ours: bool = authority.owner_of(authority.territory) == PongNetAuthority.SERVER_ID
	if was_master or (pending and ours):
		var s: PongState = match_node.snapshot
		issue(
			PongNetProtocol.TRANSFER_TAKEOVER,
			s.territory,
			s.ball_position,
			s.ball_velocity,
			s.ball_spin,
			0
		)


## Server: issues the next transfer to everyone, itself included.
func issue(
	kind: int, territory: int, position: Vector3, velocity: Vector3, spin: Vector3, age_ms: int
) -> void:
	var transfer: Dictionary = authority.next_transfer(kind, territory)
	var args: Array = [
		transfer["epoch"], kind, territory, transfer["master"], position, velocity, spin, age_ms
	]
	send_all(&"_transfer", args)
	callv(&"_on_transfer", [authority.my_id] + args)


func _hand_off(snapshot: PongState) -> void:
	var request: Dictionary = authority.relinquish(snapshot.territory)
	if request.is_empty():
		return
	var args: Array = [request["epoch"], request["territory"]] + _ball_of(snapshot)
	if authority.my_id == PongNetAuthority.SERVER_ID:
		callv(&"_on_request", [authority.my_id] + args)
	else:
		send_to(PongNetAuthority.SERVER_ID, &"_request", args)


## The ball as the master gives it: the corrected one (a hand-off's correction may still be
## gliding in), which followers and the server aim at.
func _ball_of(snapshot: PongState) -> Array:
	var corrected: Vector3 = snapshot.ball_position + snapshot.ball_correction
	return [corrected, snapshot.ball_velocity, snapshot.ball_spin]


## How old a message of [param sender] stamped with its servo time [param sent_at] is, s
## ([method PongNetLatency.age_of]).
func _age_of(sender: int, sent_at: float, reported_leg_ms: int = -1) -> float:
	var on_server: bool = authority.my_id == PongNetAuthority.SERVER_ID
	return _latency.age_of(on_server, sender, sent_at, reported_leg_ms)


func _reject(sender: int, what: String, reason: String) -> void:
	report.refuse(what)
	super(sender, what, reason)


# --- handlers of PongNetWire, with the sender's id ---


func _on_ball(
	sender: int,
	epoch: Variant,
	seq: Variant,
	time_s: Variant,
	position: Variant,
	velocity: Variant,
	spin: Variant,
	leg_ms: Variant
) -> void:
	if not _running:
		return
	var reason: String = PongNetProtocol.check_ball(
		epoch, seq, time_s, position, velocity, spin, match_node.court, _max_spin()
	)
	if reason.is_empty():
		reason = PongNetProtocol.check_int(leg_ms, 0, 10000, "leg")
	if not reason.is_empty():
		_reject(sender, "ball state", reason)
		return
	var state_epoch: int = epoch
	var state_seq: int = seq
	var sent_at: float = time_s
	var leg: int = leg_ms
	# The stream is unordered: the authority judges the epoch and the sender, the buffer the
	# order (a state older than the newest may fill a gap).
	reason = authority.accept_state(sender, state_epoch, state_seq)
	var in_stream: bool = state_epoch == authority.epoch and sender == authority.master_peer
	if not reason.is_empty() and not in_stream:
		report.late += 1
		return
	var arrival: float = PongNetBall.clock_s()
	var age: float = _age_of(sender, sent_at, leg)
	var state: PongNetBallBuffer.State = PongNetBallBuffer.State.new(
		state_seq, sent_at, [position, velocity, spin], arrival, age
	)
	var taken: PongNetBallBuffer.Taken = ball.take(state)
	if taken == PongNetBallBuffer.Taken.DUPLICATE or taken == PongNetBallBuffer.Taken.LATE:
		report.late += 1
		return
	report.states += 1
	report.ages.append(age)


func _on_request(
	sender: int,
	epoch: Variant,
	territory: Variant,
	position: Variant,
	velocity: Variant,
	spin: Variant
) -> void:
	if not _running or authority.my_id != PongNetAuthority.SERVER_ID:
		return
	var reason: String = PongNetProtocol.check_ball(
		epoch, 0, 0.0, position, velocity, spin, match_node.court, _max_spin()
	)
	if reason.is_empty():
		reason = PongNetProtocol.check_int(territory, 0, authority.owners.size() - 1, "territory")
	if not reason.is_empty():
		_reject(sender, "hand-off request", reason)
		return
	var seen: int = epoch
	var to: int = territory
	var state: Array[Vector3] = [position, velocity, spin]
	if not authority.check_request(sender, seen, to).is_empty():
		return  # A race with a newer transfer (the authority counts it), not a bad message.
	var age_ms: int = _latency.leg_ms(sender)
	issue(PongNetProtocol.TRANSFER_HANDOFF, to, state[0], state[1], state[2], age_ms)


func _on_transfer(
	sender: int,
	epoch: Variant,
	kind: Variant,
	territory: Variant,
	master: Variant,
	position: Variant,
	velocity: Variant,
	spin: Variant,
	age_ms: Variant
) -> void:
	if not _running:
		return
	var reason: String = PongNetProtocol.check_ball(
		epoch, 0, 0.0, position, velocity, spin, match_node.court, _max_spin()
	)
	for extra: String in [
		PongNetProtocol.check_int(kind, 0, PongNetProtocol.TRANSFER_NAMES.size() - 1, "kind"),
		PongNetProtocol.check_int(territory, 0, authority.owners.size() - 1, "territory"),
		PongNetProtocol.check_int(master, 0, 1 << 31, "master"),
		PongNetProtocol.check_int(age_ms, 0, 10000, "age"),
	]:
		reason = extra if reason.is_empty() else reason
	if reason.is_empty():
		var transfer: Dictionary = {
			"epoch": epoch, "kind": kind, "territory": territory, "master": master
		}
		reason = authority.apply_transfer(sender, transfer)
	if not reason.is_empty():
		_reject(sender, "transfer", reason)
		return
	report.transfer(authority.history[-1])
	ball.restart()
	_master_velocity = Vector3.INF
	var state: Array[Vector3] = [position, velocity, spin]
	var sent_age_ms: int = age_ms
	var age: float = (sent_age_ms + _latency.my_leg_ms()) / 1000.0
	var target: Array[Vector3] = PongNetSmoother.extrapolate(
		_predictor, state[0], state[1], _gravity(), age
	)
	var local: Vector3 = ball.local()[0]
	report.handoff_corrections.append((target[0] - local).length())
	var serve: bool = kind == PongNetProtocol.TRANSFER_SERVE
	ball.transfer(serve, [target[0], target[1], state[2]], age, PongNetBall.clock_s())
	_settle_until = match_node.snapshot.time_s + SETTLE_S


func _on_owners(sender: int, owners: Variant) -> void:
	if sender != PongNetAuthority.SERVER_ID or typeof(owners) != TYPE_PACKED_INT64_ARRAY:
		_reject(sender, "owners", "not from the server or not a PackedInt64Array")
		return
	var list: PackedInt64Array = owners
	if list.size() != authority.owners.size():
		_reject(
			sender, "owners", "%d seats, the match has %d" % [list.size(), authority.owners.size()]
		)
		return
	authority.owners = list
	owners_changed.emit()


func _on_event(event: PongEvent) -> void:
	if floor_hurts != null:
		floor_hurts.on_event(event)


func _on_match_over(winner: int) -> void:
	report.winner = winner
	finished.emit(winner)


## A paddle this peer drives touched the ball ([method PongNetBall.touched]).
func _on_ball_touch(event: PongEvent) -> void:
	var paddle: bool = event.type == PongServoFacts.PongEventType.PADDLE
	if paddle and local_seats.has(event.player):
		ball.touched(PongNetBall.clock_s())


func _gravity() -> float:
	return 0.0 if match_node.beginner else match_node.court.gravity


func _max_spin() -> float:
	return match_node.court.settings.max_spin_rad_per_s
