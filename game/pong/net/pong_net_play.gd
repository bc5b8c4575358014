class_name PongNetPlay
extends Node
## One networked match on this peer: the private haptic space. Every peer runs the servo and
## simulates the ball; the owner of the territory the ball is in is its master
## ([PongNetAuthority]): it sends the ball state on every new servo state (>= 60 Hz, unreliable,
## its own channel), and its contact with the ball stays in its own servo at 1 kHz whatever the
## latency. Followers play the received states out in order from a jitter buffer, carry each
## forward to now, and the servo blends their ball onto it ([PongNetBall]); the server first checks
## each against its own simulation ([PongNetBallCheck]). Each peer sends the poses of the paddles
## it drives; other peers' paddles are kinematic inputs of the local servo ([PongNetPoses]). Health
## changes come as reliable messages: floor bounces from the server, which judges the master's
## claims ([PongNetFloorHurts]), weapon hurts from the victim's peer ([PongNetWeapons]). Every
## message comes and goes through the session's [PongNetRouter], which has checked its fields; the
## node that owns its state checks it against the match, and a bad one is dropped and counted
## against its sender ([method PongNetSession.misbehaved]). Messages are aged by [PongNetLatency].
## The node lives as long as the session; its handlers and those of the match's parts are
## registered for each match.

## Health changed on every peer the same way; the match is over on every peer.
signal finished(winner: int)
## This peer, the master, sent a ball state.
signal ball_state_sent
## A state of the master's ball was taken into the jitter buffer, [param age_s] old.
signal ball_state_taken(sender: int, age_s: float)
## A state of the master's ball came too late to play (an old epoch or one the play passed).
signal ball_state_late
## A transfer was applied ([param transfer]: epoch, kind, territory, master); the ball here
## was [param correction_m] from where the transfer put it.
signal transferred(transfer: Dictionary, correction_m: float)

## Servo seconds after a transfer during which the servo's state is not trusted: the
## set_ball of the transfer reaches the servo a tick later (no hand-off request, no
## stream from a state the transfer has not replaced yet); from the servo's time at the
## transfer, as the frame's state may be a frame older (docs/pong-networking.md).
const SETTLE_S: float = 0.02
## Seconds of simulation the game steps per chunk in stepped mode.
const CHUNK_S: float = PongMatch.STEP_CHUNK_S
## The streams send on each new servo state, at most this often (a headless or fast
## machine renders hundreds of frames a second), Hz.
const MAX_STREAM_HZ: float = 125.0

## The connection; its router carries every message.
var session: PongNetSession = null
var authority: PongNetAuthority = null
var match_node: PongMatch = null
## The match's bullets and mines, paddle poses and floor hurts while a match runs.
var weapons: PongNetWeapons = null
var poses: PongNetPoses = null
var floor_hurts: PongNetFloorHurts = null
## Our ball in the servo, as the network moves it.
var ball: PongNetBall = PongNetBall.new()
## Server: the check of the master's ball against its own simulation, and the watch on its
## stream (null on a client).
var ball_check: PongNetBallCheck = null
var dry_watch: PongNetStreamWatch = null
## Who plays each seat; on the server, the computer standing in.
var seats: PongNetSeats = PongNetSeats.new()
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
# The servo's time when the last transfer was applied (s).
var _transferred_at: float = -INF
var _owe_s: float = 0.0
var _last_now: float = 0.0
var _running: bool = false
## The ball's velocity as its master last streamed it (Vector3.INF: none since the last
## transfer): what the server judges a stall by while it follows.
var _master_velocity: Vector3 = Vector3.INF
var _stale_states: PongNetNoise = PongNetNoise.new(PongNetProtocol.STALE_STATES_PER_S)
var _stale_requests: PongNetNoise = PongNetNoise.new(PongNetProtocol.STALE_REQUESTS_PER_S)


## Starts following [param p_match] (already started) with [param p_authority].
func begin(
	p_match: PongMatch, p_authority: PongNetAuthority, p_local_seats: PackedInt32Array
) -> void:
	match_node = p_match
	authority = p_authority
	local_seats = p_local_seats
	ball.court = match_node.court
	_predictor = PongPredictor.new(match_node.court)
	match_node.event_seen.connect(_on_event)
	match_node.event_seen.connect(_on_ball_touch)
	match_node.match_over.connect(_on_match_over)
	if _latency == null:
		_latency = PongNetLatency.new(session)
	var router: PongNetRouter = session.router
	router.handle(PongNetBallMessage.SCHEMA_ID, _on_ball)
	router.handle(PongNetHandOffMessage.SCHEMA_ID, _on_request)
	router.handle(PongNetTransferMessage.SCHEMA_ID, _on_transfer)
	seats.begin(router, match_node, authority, take_ball, _reject)
	weapons = PongNetWeapons.new(router, match_node, authority, _reject, _age_of)
	poses = PongNetPoses.new(router, match_node, authority, _reject, _age_of)
	floor_hurts = PongNetFloorHurts.new(router, match_node, authority, _reject)
	if authority.my_id == PongNetAuthority.SERVER_ID:
		ball_check = PongNetBallCheck.new(match_node.court, floor_hurts.judge, authority)
		poses.pose_received.connect(ball_check.note_pose)
		dry_watch = PongNetStreamWatch.new(authority, session.pulse.heartbeat, _reject, take_ball)
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
	for part: Object in [self, weapons, poses, floor_hurts, seats]:
		session.router.forget(part)
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
		if not _running:
			return  # The match ended in those steps (end() let go of the poses and weapons).
		if chunks == 0:
			return  # Nothing moved since the last frame: the rest would see the same state.
	# After the stepping: the target is carried to now, where the servo is.
	if not authority.is_master() and ball.follow(PongNetBall.clock_s(), _predictor, _gravity()):
		# Only the newest state played becomes a command to the servo (whose queue holds 64).
		_master_velocity = ball.buffer.played.velocity
		floor_hurts.observe_master(ball.buffer.just_played, PongNetBall.clock_s())
	var snapshot: PongState = match_node.snapshot
	var sim_dt: float = match_node.now - _last_now
	_last_now = match_node.now
	if authority.my_id == PongNetAuthority.SERVER_ID:
		_referee(sim_dt)
		dry_watch.update(sim_dt, PongNetPulse.now_s())
		var owed: PongNetBallCheck.Owed = ball_check.owed_hand_off(authority, floor_hurts.now())
		if owed != null:
			var handoff: PongNetFacts.TransferKind = PongNetFacts.TransferKind.HANDOFF
			issue(handoff, owed.territory, owed.position, owed.velocity, owed.spin, owed.age_ms)
	var settled: bool = snapshot.time_s > _transferred_at + SETTLE_S
	if authority.is_master() and settled and snapshot.territory != authority.territory:
		_hand_off(snapshot)
	var due: bool = snapshot.time_s - _last_sent_time >= 1.0 / MAX_STREAM_HZ
	if authority.is_master() and settled and due:
		_last_sent_time = snapshot.time_s
		_seq += 1
		var leg_ms: int = _latency.up_ms()
		session.router.send_all(PongNetBall.state_of(snapshot, authority.epoch, _seq, leg_ms))
		ball_state_sent.emit()
	if snapshot.time_s - _last_pose_time >= 1.0 / MAX_STREAM_HZ:
		_last_pose_time = snapshot.time_s
		poses.send(snapshot, local_seats, _latency.up_ms())
	floor_hurts.observe(snapshot)


func _referee(sim_dt: float) -> void:
	var rules: PongRules = match_node.rules
	var velocity: Vector3 = match_node.snapshot.ball_velocity
	if not authority.is_master() and _master_velocity != Vector3.INF:
		# A follower's ball falls between the master's states, lifted back by each correction:
		# at rest it never looked still here (a ball dead 150 ms away went unserved for 5 s).
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
	var serving: PongNetFacts.TransferKind = PongNetFacts.TransferKind.SERVE
	issue(serving, territory, serve.position, serve.velocity, Vector3.ZERO, 0)


## Server: a takeover from the server's own ball; its master is the owner of the ball's
## territory, or [param master] when given.
func take_ball(master: int = -1) -> void:
	var s: PongState = match_node.snapshot
	var takeover: PongNetFacts.TransferKind = PongNetFacts.TransferKind.TAKEOVER
	issue(takeover, s.territory, s.ball_position, s.ball_velocity, s.ball_spin, 0, master)


## Server: issues the next transfer to everyone, itself included.
func issue(
	kind: PongNetFacts.TransferKind,
	territory: int,
	position: Vector3,
	velocity: Vector3,
	spin: Vector3,
	age_ms: int,
	master: int = -1
) -> void:
	var next: Dictionary = authority.next_transfer(kind, territory, master)
	var transfer: PongNetTransferMessage = PongNetTransferMessage.new()
	transfer.epoch = next["epoch"]
	transfer.kind = kind
	transfer.territory = territory
	transfer.master = next["master"]
	transfer.position = position
	transfer.velocity = velocity
	transfer.spin = spin
	transfer.age_ms = age_ms
	# Twice at first: a transfer lost on a lossy path held the ball until the resend, while
	# the new master's paddle struck it and the old one flew it on.
	session.router.send_all(transfer, 2)
	_on_transfer(authority.my_id, transfer)


# The master's ball crossed into another territory: it asks the server for the hand-off,
# with the ball as it gives it (the corrected one: a hand-off's correction may still be
# gliding in).
func _hand_off(snapshot: PongState) -> void:
	var relinquished: Dictionary = authority.relinquish(snapshot.territory)
	if relinquished.is_empty():
		return
	var request: PongNetHandOffMessage = PongNetHandOffMessage.new()
	request.epoch = relinquished["epoch"]
	request.territory = relinquished["territory"]
	request.position = snapshot.ball_position + snapshot.ball_correction
	request.velocity = snapshot.ball_velocity
	request.spin = snapshot.ball_spin
	if authority.my_id == PongNetAuthority.SERVER_ID:
		_on_request(authority.my_id, request)
	else:
		session.router.send_to(PongNetAuthority.SERVER_ID, request)


## How old a message of [param sender] stamped with its servo time [param sent_at] is, s
## ([method PongNetLatency.age_of]).
func _age_of(sender: int, sent_at: float, reported_leg_ms: int = -1) -> float:
	var on_server: bool = authority.my_id == PongNetAuthority.SERVER_ID
	return _latency.age_of(on_server, sender, sent_at, reported_leg_ms)


func _reject(sender: int, what: String, reason: String) -> void:
	# Refused either way; not counted when it may come from a player's time cut off.
	if not seats.cut_off_lately(sender):
		session.misbehaved(sender, what, reason)


# --- received, their fields checked (PongNetRouter): the checks against this match ---


func _on_ball(sender: int, state: PongNetBallMessage) -> void:
	if not _running:
		return
	var reason: String = PongNetProtocol.check_ball(
		state.position, state.velocity, state.spin, match_node.court, _max_spin()
	)
	if not reason.is_empty():
		_reject(sender, PongNetBallMessage.LABEL, reason)
		return
	# The stream is unordered: the authority judges the epoch and the sender, the buffer the
	# order (a state older than the newest may fill a gap).
	reason = authority.accept_state(sender, state.epoch, state.seq)
	var in_stream: bool = state.epoch == authority.epoch and sender == authority.master_peer
	if not reason.is_empty() and not in_stream:
		ball_state_late.emit()
		if _stale_states.note(sender, PongNetBall.clock_s()):
			_reject(sender, PongNetBallMessage.LABEL, "a stream of stale states")
		return
	var arrival: float = PongNetBall.clock_s()
	var age: float = _age_of(sender, state.time_s, state.leg_ms)
	if age == PongNetClock.REFUSED:
		_reject(
			sender,
			PongNetBallMessage.LABEL,
			"time %.3f s: its clock cannot have made it" % state.time_s
		)
		return
	if ball_check != null:
		var outcome: PongNetBallCheck.Outcome = ball_check.admit(state, age, floor_hurts.now())
		if outcome == PongNetBallCheck.Outcome.REFUSE:
			_reject(sender, PongNetBallMessage.LABEL, ball_check.reason)
		if outcome != PongNetBallCheck.Outcome.PLAY:
			return
		dry_watch.fed()
	session.router.forward(sender, state)
	var buffered: PongNetBallBuffer.State = PongNetBallBuffer.State.new(
		state.seq, state.time_s, [state.position, state.velocity, state.spin], arrival, age
	)
	var taken: PongNetBallBuffer.Taken = ball.take(buffered)
	if taken == PongNetBallBuffer.Taken.DUPLICATE or taken == PongNetBallBuffer.Taken.LATE:
		ball_state_late.emit()
		return
	ball_state_taken.emit(sender, age)


func _on_request(sender: int, request: PongNetHandOffMessage) -> void:
	if not _running or authority.my_id != PongNetAuthority.SERVER_ID:
		return
	var reason: String = PongNetProtocol.check_ball(
		request.position, request.velocity, request.spin, match_node.court, _max_spin()
	)
	if reason.is_empty():
		reason = PongNetProtocol.check_seat(request.territory, authority.owners.size(), "territory")
	if not reason.is_empty():
		_reject(sender, PongNetHandOffMessage.LABEL, reason)
		return
	if not authority.check_request(sender, request.epoch, request.territory).is_empty():
		# A race with a newer transfer (the authority counts it), not a bad message; a stream
		# of them is.
		if _stale_requests.note(sender, PongNetBall.clock_s()):
			_reject(sender, PongNetHandOffMessage.LABEL, "a stream of stale hand-off requests")
		return
	var handoff: PongNetFacts.TransferKind = PongNetFacts.TransferKind.HANDOFF
	var age_ms: int = _latency.from_ms(sender)
	issue(handoff, request.territory, request.position, request.velocity, request.spin, age_ms)


func _on_transfer(sender: int, transfer: PongNetTransferMessage) -> void:
	if not _running:
		return
	var reason: String = PongNetProtocol.check_ball(
		transfer.position, transfer.velocity, transfer.spin, match_node.court, _max_spin()
	)
	if reason.is_empty():
		reason = PongNetProtocol.check_seat(
			transfer.territory, authority.owners.size(), "territory"
		)
	if reason.is_empty():
		var entry: Dictionary = {
			"epoch": transfer.epoch,
			"kind": transfer.kind,
			"territory": transfer.territory,
			"master": transfer.master,
		}
		reason = authority.apply_transfer(sender, entry)
	if not reason.is_empty():
		_reject(sender, PongNetTransferMessage.LABEL, reason)
		return
	ball.restart()
	_master_velocity = Vector3.INF
	var age: float = (transfer.age_ms + _latency.down_ms()) / 1000.0
	var target: Array[Vector3] = PongNetSmoother.extrapolate(
		_predictor, transfer.position, transfer.velocity, _gravity(), age
	)
	if ball_check != null:
		ball_check.restart([target[0], target[1], transfer.spin], floor_hurts.now())
	transferred.emit(authority.history[-1], (target[0] - ball.local()[0]).length())
	var serve: bool = transfer.kind == PongNetFacts.TransferKind.SERVE
	ball.transfer(serve, [target[0], target[1], transfer.spin], age, PongNetBall.clock_s())
	_transferred_at = PongServo.shared().get_state().time_s


# An event from before the last transfer reached the servo (read up to a frame late) is
# the epoch before's: not a new master's to claim.
func _on_event(event: PongEvent) -> void:
	if floor_hurts != null:
		floor_hurts.on_event(event, event.time_s < _transferred_at + PongServo.COMMAND_LANDS_S)


func _on_match_over(winner: int) -> void:
	finished.emit(winner)


## A paddle this peer drives touched the ball ([method PongNetBall.touched]).
func _on_ball_touch(event: PongEvent) -> void:
	var paddle: bool = event.type == PongServoFacts.PongEventType.PADDLE
	if paddle and local_seats.has(event.player):
		ball.touched(PongNetBall.clock_s(), _latency.touch_reach_s() + ball.buffer.delay_s)


func _gravity() -> float:
	return 0.0 if match_node.beginner else match_node.court.gravity


func _max_spin() -> float:
	return match_node.court.settings.max_spin_rad_per_s
