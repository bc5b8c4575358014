class_name PongMatch
extends Node
## One match of Haptic Battle Pong: it drives the servo's Pong renderer through
## [code]PongServo.shared()[/code] and keeps the rules. Every update it reads the newest state and
## the events (floor bounces cost health, paddle contacts end the computer's swing), moves
## the bullets, sets mines off, asks each player's controller what it does, fires, places
## mines, serves when due, and hands the servo the input. The ball itself is only ever in
## the servo. Its hold on the servo is a [PongServoLink]; what the weapons make the player
## at the device feel, a [PongHandFeedback].
##
## Real time: one update per rendered frame, the servo thread at 1 kHz. [member stepped]:
## the servo thread is stopped and each physics frame runs updates of
## [constant STEP_CHUNK_S] followed by as many [code]step(0.001)[/code] ticks, as many as
## [member stepped_speed] asks (0: as many as fit in [constant STEP_BUDGET_MS] of wall
## time), so a headless match runs faster than real time.

## A servo event ([method PongServo.drain_events]) was read.
signal event_seen(event: PongEvent)
## A serve was made toward [param receiver].
signal served(receiver: int)
signal health_changed(player: int, health: int, cause: StringName)
signal mine_placed(mine: PongMines.Mine)
signal mine_exploded(mine: PongMines.Mine, victim: int)
signal bullet_fired(bullet: PongBullets.Bullet)
## [param hit]: {owner, victim, position, direction}.
signal bullet_hit(hit: Dictionary)
signal match_over(winner: int)
## With more than two players: [param player] ran out of health and is out.
signal player_out(player: int)

## VS_COMPUTER: player 0 is the device (or keyboard), the others the computer.
## TWO_PLAYERS: players 0 and 1 are people, players 2 and 3 (four-player court) the
## computer. DEMO: the computer plays every side.
enum Mode { VS_COMPUTER, TWO_PLAYERS, DEMO }

const STEP_CHUNK_S: float = 0.01
## Seconds the computer keeps its weapons away against people: time to find the paddle.
const WEAPONS_GRACE_S: float = 20.0
const STEP_BUDGET_MS: float = 14.0

@export var mode: Mode = Mode.VS_COMPUTER
@export var beginner: bool = false
@export var start_health: int = PongRules.DEFAULT_START_HEALTH
## 2, or 4 on a square court (the servo's pong.players, set at start and restored after).
@export_enum("2:2", "4:4") var players: int = 2
## Run the servo by hand (no thread), faster than real time when it can.
@export var stepped: bool = false
## Simulated seconds per wall second in stepped mode (0: as fast as it goes).
@export var stepped_speed: float = 0.0
## Serve at the start, after stalls and after beginner goals (tests serve themselves).
@export var auto_serve: bool = true
## Seed of the computer players' randomness.
@export var ai_seed: int = 1
## Stepped mode: step from the physics frames (off: whoever owns the match calls
## [method run_until], e.g. a test).
@export var self_stepping: bool = true
## Floor and goal events cost health here (off in a networked match: the ball's master
## applies them and tells every peer).
@export var rules_from_events: bool = true
## Bullets and mines.
@export var weapons: bool = true
## How hard the computer plays against people (in DEMO, networked too: NORMAL, armed).
@export var difficulty: PongAiLevel.Level = PongAiLevel.Level.EASY

var court: PongCourt = null
var rules: PongRules = null
var mines: PongMines = PongMines.new()
var effects: PongEffects = PongEffects.new()
var bullets: PongBullets = PongBullets.new()
var referee: PongReferee = PongReferee.new()
## Who judges the weapons' hits and where their hurts go (a networked match sets its own).
var weapon_referee: PongWeaponReferee = PongWeaponReferee.new()
## One per player.
var controllers: Array[PongController] = []
## The player on the device (0), or -1 when no paddle is the device's.
var local_player: int = -1
## The newest servo state.
var snapshot: PongState = PongState.new()
## Match time, seconds (simulated time in stepped mode).
var now: float = 0.0
## The paddle's reach from the avatar: the device workspace radius times the scale.
var reach: float = 0.0

var _started: bool = false
var _servo: PongServoLink = PongServoLink.new()
var _feedback: PongHandFeedback = null
var _device_orientation: bool = false
var _wall_start_us: int = 0
var _paused_ball: PongState = null


## Sets the match up and starts it; false (and nothing changes) without the Pong renderer.
func start() -> bool:
	if not PongServo.shared().is_available():
		return false
	if not _servo.claim_court(players, beginner):
		return false
	court = PongCourt.from_settings(PongServo.shared().get_settings())
	_feedback = PongHandFeedback.new(court)
	effects.ramp_s = court.settings.mine_effect_ramp_s
	rules = PongRules.new(start_health, court.players)
	rules.health_changed.connect(health_changed.emit)
	rules.match_over.connect(_on_match_over)
	rules.player_out.connect(_on_player_out)
	referee.players = court.players
	var radius: float = Haptics.device.get_workspace_radius()
	reach = radius * court.workspace_scale
	effects.reach = reach
	local_player = 0 if mode != Mode.DEMO and _servo.device_usable() else -1
	_device_orientation = _servo.device_has_orientation()
	controllers.clear()
	for player: int in court.players:
		controllers.append(_make_controller(player, radius))
	_retarget()
	_servo.enter(stepped)
	PongServo.shared().set_ball(Vector3(0.0, court.ball_radius, 0.0), Vector3.ZERO)
	# No state of this match yet, but the servo's clock runs on from match to match: what
	# reads the state before the first update (a network play, earlier in the frame) reads
	# its time, not 0.
	snapshot = PongState.new()
	snapshot.time_s = PongServo.shared().get_state().time_s
	_send_input()
	_wall_start_us = Time.get_ticks_usec()
	_started = true
	return true


func _exit_tree() -> void:
	if _started:
		_servo.leave()


func _notification(what: int) -> void:
	if not _started or stepped:
		return
	# The servo runs on while the game is paused: the ball is put back where it was.
	if what == NOTIFICATION_PAUSED:
		_paused_ball = snapshot
		_send_input()
	elif what == NOTIFICATION_UNPAUSED and _paused_ball != null:
		PongServo.shared().set_ball(
			_paused_ball.ball_position, _paused_ball.ball_velocity, _paused_ball.ball_spin
		)
		PongServo.shared().drain_events()
		_paused_ball = null
		_send_input()


func _process(delta: float) -> void:
	if _started and not stepped:
		advance(minf(delta, 0.1))


func _physics_process(delta: float) -> void:
	if not _started or not stepped or not self_stepping:
		return
	var wall_start: int = Time.get_ticks_usec()
	var chunks: int = maxi(1, roundi(delta * stepped_speed / STEP_CHUNK_S))
	var done: int = 0
	while stepped_speed <= 0.0 or done < chunks:
		_step_chunk()
		done += 1
		if rules.is_over() or Time.get_ticks_usec() - wall_start > STEP_BUDGET_MS * 1000.0:
			break


## Stepped mode: updates and servo ticks, [constant STEP_CHUNK_S] at a time, until
## [param condition] holds (checked after each) or [param max_s] simulated seconds have
## passed. Returns whether it held.
func run_until(condition: Callable, max_s: float) -> bool:
	var end: float = now + max_s
	while now < end:
		_step_chunk()
		if condition.call():
			return true
	return false


## One update of [param dt] seconds (the servo runs separately: its thread, or the ticks
## of stepped mode).
func advance(dt: float) -> void:
	now += dt
	snapshot = PongServo.shared().get_state()
	for event: PongEvent in PongServo.shared().drain_events():
		_on_event(event)
	effects.advance(dt)
	_move_bullets(dt)
	_check_mines()
	_decide(dt)
	if auto_serve and not rules.is_over() and referee.update(dt, snapshot.ball_velocity):
		serve()
	_send_input()


## Serves now toward the referee's receiver.
func serve() -> void:
	var receiver: int = next_receiver()
	var ball: PongReferee.Serve = referee.make_serve(
		court, controllers[receiver].intent.avatar, beginner
	)
	PongServo.shared().set_ball(ball.position, ball.velocity)
	served.emit(receiver)


## The referee's receiver, moved on past the players who are out.
func next_receiver() -> int:
	for skip: int in court.players:
		if not rules.is_out(referee.receiver):
			break
		referee.receiver = (referee.receiver + 1) % court.players
	return referee.receiver


## Simulated seconds per wall second since the start.
func speed_ratio() -> float:
	var wall: float = (Time.get_ticks_usec() - _wall_start_us) / 1e6
	return now / wall if wall > 0.0 else 0.0


## The largest |force on the hand| (N, device space) since the last call: every servo
## tick's total from the telemetry while the servo thread runs (a ball's contact lasts
## about 40 ms and falls between frames), else the newest state's.
func take_peak_force() -> float:
	var peak: float = snapshot.hand_force.total.length()
	return peak if stepped else _servo.peak_force(peak)


## The avatar of [param player].
func avatar_of(player: int) -> Vector3:
	return controllers[player].intent.avatar


## [param player]'s mine effect and the seconds it has left, or null: the servo's countdown
## for the device player, the game's for a kinematic one.
func effect_of(player: int) -> PongEffectState:
	if player == local_player:
		for entry: PongEffectState in snapshot.effects:
			if PongMines.KINDS.has(PongServoFacts.PONG_EFFECT_KIND_NAMES[entry.kind]):
				return entry
		return null
	return effects.state_of(player)


# The ticks first: the update then reads the state they made and sends the input for the
# next ones.
func _step_chunk() -> void:
	PongServo.shared().step_ticks(roundi(STEP_CHUNK_S / PongServo.TICK_S))
	advance(STEP_CHUNK_S)


func _unhandled_input(event: InputEvent) -> void:
	if not _started:
		return
	var size: Vector2 = get_viewport().get_visible_rect().size
	for controller: PongController in controllers:
		controller.handle_input(event, size)


func _make_controller(player: int, radius: float) -> PongController:
	var controller: PongController
	if mode == Mode.DEMO or (mode == Mode.VS_COMPUTER and player != 0) or player >= 2:
		var ai: PongAi = PongAi.new(player, court, reach, ai_seed + player)
		ai.beginner = beginner
		if mode != Mode.DEMO:
			ai.weapons_from_s = WEAPONS_GRACE_S
			PongAiLevel.apply(ai, difficulty)
		controller = ai
	else:
		var scheme: PongHumanPlayer.Scheme = (
			PongHumanPlayer.Scheme.DEVICE if player == 0 else PongHumanPlayer.Scheme.KEYBOARD
		)
		controller = PongHumanPlayer.new(player, scheme, court, reach, radius)
	controller.kinematic = player != local_player
	return controller


func _on_event(event: PongEvent) -> void:
	var hurt: int = rules.apply_event(event, court, beginner) if rules_from_events else -1
	if hurt >= 0 and beginner and event.type == PongServoFacts.PongEventType.WALL:
		referee.serve_after(PongReferee.GOAL_SERVE_DELAY_S)
	for controller: PongController in controllers:
		controller.notice(event, now)
	event_seen.emit(event)


func _move_bullets(dt: float) -> void:
	var avatars: Array[Vector3] = []
	for player: int in court.players:
		# A player who is out is off the court: far below it, where no bullet flies.
		avatars.append(avatar_of(player) if not rules.is_out(player) else Vector3.DOWN * 100.0)
	for hit: Dictionary in bullets.advance(dt, court, avatars):
		var victim: int = hit["victim"]
		var direction: Vector3 = hit["direction"]
		if not weapon_referee.judges(victim):
			continue
		if victim == local_player:
			_feedback.hit(victim, direction)
		var shooter: int = hit["owner"]
		var shot: int = hit["id"]
		weapon_referee.hurt(rules, victim, PongRules.CAUSE_BULLET, shooter, shot)
		bullet_hit.emit(hit)


func _check_mines() -> void:
	for player: int in court.players:
		if rules.is_out(player) or not weapon_referee.judges(player):
			continue
		var mine: PongMines.Mine = mines.step_on(player, avatar_of(player))
		if mine == null:
			continue
		var duration: float = court.settings.mine_effect_duration_s
		if mine.kind != "none" and player != local_player:
			effects.start(player, mine.kind, duration, mine.owner)
		if player == local_player:
			_feedback.mine(player, mine.kind, duration, mine.owner)
		weapon_referee.hurt(rules, player, PongRules.CAUSE_MINE, mine.owner, mine.id)
		mine_exploded.emit(mine, player)


func _decide(dt: float) -> void:
	for player: int in court.players:
		if rules.is_out(player):
			continue
		var controller: PongController = controllers[player]
		controller.speed_factor = effects.speed_factor(player)
		var other: Vector3 = avatar_of(rules.opponent_in(player))
		var intent: PongIntent = controller.update(now, dt, snapshot, other)
		if intent.fire and intent.gun and weapons and not rules.is_over():
			_fire(player)
		if intent.place_mine and weapons and not rules.is_over():
			var mine: PongMines.Mine = mines.place(player, intent.avatar, court, _standing(player))
			if mine != null:
				mine_placed.emit(mine)


# The gun's axis is the paddle's normal: the device's own when it reports an orientation,
# else the one the game sends this update.
func _fire(player: int) -> void:
	var axis: Vector3 = controllers[player].intent.normal
	if player == local_player and _device_orientation:
		axis = snapshot.paddle_normals[player]
	var bullet: PongBullets.Bullet = bullets.fire(player, snapshot.paddle_centers[player], axis)
	if bullet == null:
		return
	if player == local_player:
		_feedback.recoil(player, axis)
	bullet_fired.emit(bullet)


func _send_input() -> void:
	var input: PongInput = PongInput.new()
	input.beginner = beginner
	input.local_player = local_player
	for player: int in court.players:
		var controller: PongController = controllers[player]
		var entry: PongPlayerInput = controller.intent.to_input(controller.kinematic)
		if controller.kinematic:
			var effect_owner: int = effects.owner_of(player)
			var owner_offset: Vector3 = Vector3.ZERO
			if effect_owner >= 0 and controllers[effect_owner].kinematic:
				# The owner's pose as given, not the servo's paddle carried on by its velocity:
				# a remote owner's velocity includes what this pull did to its own paddle, so
				# two players with remote mines on each other across the network rang with the
				# carried-on poses in the loop (offsets of 3 m and more).
				owner_offset = controllers[effect_owner].intent.paddle_offset
			elif effect_owner >= 0:
				owner_offset = snapshot.paddle_centers[effect_owner] - avatar_of(effect_owner)
			entry.paddle_offset = effects.affect_offset(
				player, controller.intent.paddle_offset, owner_offset
			)
		entry.active = _paused_ball == null and not rules.is_out(player)
		input.players[player] = entry
	PongServo.shared().set_input(input)


func _on_match_over(winner: int) -> void:
	match_over.emit(winner)


func _on_player_out(player: int) -> void:
	_retarget()
	player_out.emit(player)


# Where the players other than [param player] who are still in stand.
func _standing(player: int) -> Array[Vector3]:
	var spots: Array[Vector3] = []
	for other: int in court.players:
		if other != player and not rules.is_out(other):
			spots.append(avatar_of(other))
	return spots


# The computer plays the ball to the players still in.
func _retarget() -> void:
	var left: Array[int] = rules.alive()
	for controller: PongController in controllers:
		if controller is PongAi:
			var ai: PongAi = controller
			ai.targets.assign(left.filter(func(p: int) -> bool: return p != ai.player))
