extends "res://tests/pong/pong_screen_suite.gd"
## What the game-action tests of Pong's forces share (test_pong_felt*.gd). Each test
## performs a player's action through the game's own code (the input actions handed to the
## player's controller, the match's update, its weapons and mines, the servo's contact with
## the device paddle), steps the servo tick by tick and checks what the simulated device
## received: the servo's hand force [code]total[/code] (device space, newtons), its size,
## direction and duration. A refused effect command is an error the runner fails on, and an
## absent force fails the assertions.

const PongTestScreen := preload("res://tests/pong/pong_test_screen.gd")
const PongTestEvents := preload("res://tests/pong/pong_test_events.gd")
const PongFeltProbe := preload("res://tests/pong/pong_felt_probe.gd")
## Below this the hand feels nothing, newtons.
const QUIET_N: float = 0.02
## A pulse's size and duration tolerances: the slew limit shapes its edges (a 1.5 N edge
## takes 7.5 ms at 200 N/s) and the order reaches the servo at the next tick.
const PULSE_FORCE_TOLERANCE: float = 0.05
const PULSE_DURATION_TOLERANCE_S: float = 0.012
## A mine effect's tolerances (its ramps: 0.25 s each way).
const EFFECT_FORCE_TOLERANCE: float = 0.1
const EFFECT_END_TOLERANCE_S: float = 0.03
const VIEW_SIZE: Vector2 = Vector2(1280.0, 720.0)
## The brushing hand's sideways swing: its frequency, and its amplitude in fractions of the
## workspace radius (0.3: the paddle passes 0.15 m either side of the ball at up to 2.8 m/s).
const BRUSH_HZ: float = 3.0
const BRUSH_AMPLITUDE: float = 0.3
const WALK_ACTIONS: Array[StringName] = [&"move_left", &"move_right", &"move_up", &"move_down"]

var _match: PongMatch = null
# Where the device player's hand waits while walking onto a mine (fractions of the radius).
var _hand_on_mine: Vector2 = Vector2.ZERO
var _probe: PongFeltProbe = null
var _events: Array[PongEvent] = []


func after_each() -> void:
	for action: StringName in WALK_ACTIONS:
		Input.action_release(action)
	_match = null
	_hand_on_mine = Vector2.ZERO
	_probe = null
	_events.clear()
	await _free_pong()


# --- The actions ----------------------------------------------------------------------


# The Pong screen in [param mode], stepped by this test; the computer holds its weapons,
# the people's controllers read input (the actions this test hands them). False (and a
# failure) without the Pong renderer or the simulated device.
func _open(mode: PongMatch.Mode) -> bool:
	if not assert_true(PongServo.shared().is_available(), "the extension has the Pong renderer"):
		return false
	_pong = PongTestScreen.stepped(mode, 2, 99)
	_match = _pong.get_node(^"Match") as PongMatch
	add_child(_pong)
	_match.event_seen.connect(_events.append)
	for controller: PongController in _match.controllers:
		if controller is PongAi:
			(controller as PongAi).use_weapons = false
	_probe = PongFeltProbe.new(_match)
	return assert_eq(_match.local_player, 0, "player 0 plays on the simulated device")


# An input action of [param player]'s, pressed, handed to its controller as the match's
# input handler does.
func _press(player: int, action: StringName) -> void:
	var event: InputEventAction = InputEventAction.new()
	event.action = action
	event.pressed = true
	_match.controllers[player].handle_input(event, VIEW_SIZE)


# The mouse moved so that the device player's hand is at [param hand] (fractions of the
# workspace radius: x right, y up).
func _move_hand(hand: Vector2) -> void:
	var motion: InputEventMouseMotion = InputEventMouseMotion.new()
	motion.position = VIEW_SIZE * 0.5 + Vector2(hand.x, -hand.y) * VIEW_SIZE.y * 0.25
	_match.controllers[0].handle_input(motion, VIEW_SIZE)


# Player 1 throws its [param kind] mine (the place-mine key for the first kind; a later
# kind arrives as a networked match's would), and the device player walks onto it with the
# move keys. Returns the tick it went off at, or -1 (and a failure).
func _step_on_mine(kind: String) -> int:
	if not _open(PongMatch.Mode.TWO_PLAYERS):
		return -1
	_move_hand(_hand_on_mine)
	_probe.run(0.3)
	var went_off: Array[int] = []
	_match.mine_exploded.connect(
		func(_mine: PongMines.Mine, victim: int) -> void:
			if victim == 0:
				went_off.append(_probe.mark())
	)
	var mine: PongMines.Mine = null
	if kind == PongMines.KINDS[0]:
		var placed: Array[PongMines.Mine] = []
		_match.mine_placed.connect(placed.append)
		_press(1, &"p1_place_mine")
		_probe.run(0.01)
		if not assert_eq(placed.size(), 1, "the mine key threw a mine"):
			return -1
		mine = placed[0]
	else:
		var spot: Vector3 = Vector3(0.8, 0.0, 1.2)
		mine = _match.mines.put(1, PongMines.KINDS.find(kind), spot)
	var walk: Callable = func() -> bool:
		_walk_toward(mine.position)
		return not went_off.is_empty()
	if went_off.is_empty() and not _probe.run(4.0, walk):
		fail("player 0 never stepped on the %s mine" % kind)
		return -1
	for action: StringName in WALK_ACTIONS:
		Input.action_release(action)
	assert_eq(_match.rules.get_health(0), _match.rules.start_health - 5, "a mine costs 5")
	return went_off[0]


# The move keys pressed toward [param spot] (floor), released when there.
func _walk_toward(spot: Vector3) -> void:
	var gap: Vector3 = spot - _match.avatar_of(0)
	var keys: Dictionary[StringName, bool] = {
		&"move_left": gap.x < -0.05,
		&"move_right": gap.x > 0.05,
		&"move_up": gap.z < -0.05,
		&"move_down": gap.z > 0.05,
	}
	for action: StringName in keys:
		if keys[action]:
			Input.action_press(action)
		else:
			Input.action_release(action)


# The match serves to the device player, whose hand follows the ball with the mouse to
# meet it; with [param brush] the hand also swings left and right across the ball
# ([constant BRUSH_HZ], [constant BRUSH_AMPLITUDE] of the radius); a [param spin] makes the
# served ball spin so (as a ball returned with spin comes). Returns {from, to (the
# contact's first tick and the one after its last), facing (the paddle's normal toward the
# ball, device space), facing_world}, or empty (and a failure).
func _meet_serve(brush: bool, spin: Vector3 = Vector3.ZERO) -> Dictionary:
	_probe.run(0.1)
	_match.referee.receiver = 0
	_match.serve()
	if spin != Vector3.ZERO:
		# The served ball, spinning as a ball comes back after a spin shot.
		PongServo.shared().step_ticks(1)
		var served: PongState = PongServo.shared().get_state()
		PongServo.shared().set_ball(served.ball_position, served.ball_velocity, spin)
	var follow: Callable = func() -> bool:
		var ball: Vector3 = _match.snapshot.ball_position
		var offset: Vector3 = ball - _match.avatar_of(0)
		var hand: Vector2 = Vector2(offset.x, offset.y) / _match.reach
		if brush:
			hand.x += BRUSH_AMPLITUDE * sin(TAU * BRUSH_HZ * _match.now)
		_move_hand(hand.limit_length(0.95))
		return _saw(PongServoFacts.PongEventType.RELEASE, 0)
	if not assert_true(_probe.run(2.5, follow), "the device paddle met the serve"):
		return {}
	_probe.run(0.05)
	var ticks: Vector2i = _contact_ticks(0)
	var state: PongState = _probe.states[ticks.x]
	var normal: Vector3 = state.paddle_normals[0]
	var side: float = signf((state.ball_position - state.paddle_centers[0]).dot(normal))
	return {
		"from": ticks.x,
		"to": ticks.y,
		"facing": _device(0, normal * side),
		"facing_world": normal * side,
	}


# The ticks of [param player]'s latest contact: x its first, y the one after its last.
func _contact_ticks(player: int) -> Vector2i:
	var start: float = 0.0
	var end: float = 0.0
	for event: PongEvent in _events:
		if event.player != player:
			continue
		if event.type == PongServoFacts.PongEventType.PADDLE:
			start = event.time_s
		elif event.type == PongServoFacts.PongEventType.RELEASE:
			end = event.time_s
	return Vector2i(_probe.index_at(start), _probe.index_at(end))


# The ball's change across [param ticks] of a contact with [param player]'s paddle, in the
# paddle's plane, against the
# spin's grip the ball brought: -(2/7) (w0 x r n) unless friction holds it lower.
func _assert_bent_by_spin(ticks: Vector2i, player: int) -> void:
	var before: PongState = _probe.states[ticks.x]
	var after: PongState = _probe.states[ticks.y]
	var normal: Vector3 = before.paddle_normals[player]
	var side: float = signf((before.ball_position - before.paddle_centers[player]).dot(normal))
	var facing: Vector3 = normal * side
	var contact_s: float = after.time_s - before.time_s
	var change: Vector3 = (
		after.ball_velocity - before.ball_velocity - Vector3.DOWN * _match.court.gravity * contact_s
	)
	var bent: Vector3 = change - facing * change.dot(facing)
	var slip: Vector3 = before.ball_spin.cross(-facing * _match.court.ball_radius)
	var grip: Vector3 = -slip * 2.0 / 7.0
	var friction: float = _match.court.settings.surface_friction * change.dot(facing)
	var expected: float = minf(grip.length(), friction)
	print(
		(
			"    bent off player %d's paddle: %.3f m/s, the grip %.3f m/s"
			% [player, bent.length(), expected]
		)
	)
	assert_gt(expected, 0.05, "(the test's own check: the ball brought spin)")
	assert_almost_eq(bent.length(), expected, expected * 0.3 + 0.03, "bent by the spin it brought")
	assert_gt(bent.normalized().dot(grip.normalized()), 0.9, "the way the spin grips")


# --- Reading the results --------------------------------------------------------------


# A bullet's constant force: [param kind]'s ("recoil" or "hit") size and duration, along
# [param direction] (device space), starting at tick [param from].
func _assert_pulse(from: int, kind: String, direction: Vector3) -> void:
	var settings: PongSettings = _match.court.settings
	var size: float = settings.recoil_force_n if kind == "recoil" else settings.hit_force_n
	var duration: float = (
		settings.recoil_duration_s if kind == "recoil" else settings.hit_duration_s
	)
	var peak: float = _probe.peak(from)
	print("    %s: peak %.3f N for %.3f s" % [kind, peak, _probe.span_s(from, size * 0.5)])
	assert_almost_eq(peak, size, size * PULSE_FORCE_TOLERANCE, "%s: its size, newtons" % kind)
	var at: Vector3 = _probe.force(_probe.peak_index(from))
	assert_gt(at.normalized().dot(direction.normalized()), 0.98, "%s: its direction" % kind)
	assert_almost_eq(
		_probe.span_s(from, size * 0.5),
		duration,
		PULSE_DURATION_TOLERANCE_S,
		"%s: its duration, seconds" % kind
	)
	assert_lt(_probe.force(_probe.mark() - 1).length(), QUIET_N, "%s: then nothing" % kind)


func _device(player: int, world: Vector3) -> Vector3:
	return PongCourt.side_rotation(player).inverse() * world


# The device player's stylus velocity on tick [param index] (device space, m/s).
func _device_velocity(index: int) -> Vector3:
	var paddle: Vector3 = _probe.states[index].paddle_velocities[0]
	return _device(0, paddle) / _match.court.workspace_scale


func _saw(type: PongServoFacts.PongEventType, player: int) -> bool:
	return PongTestEvents.saw(_events, type, player)


# The device player's running effect of [param kind] in the servo, or null.
func _servo_effect(kind: String) -> PongEffectState:
	return PongServo.effect_in(PongServo.shared().get_state(), kind)
