extends TestSuite
## Haptic Battle Pong's renderer through [PongServo] over a door of the test's own, stepped
## manually with the simulated device: the ball flies, bounces and meets the device paddle;
## state, events, input, commands and the 3D hand target behave as the class reference
## says; bad values are refused naming the field, and change nothing.

const PongTestEvents := preload("res://tests/pong/pong_test_events.gd")
const AVATAR := Vector3(0.0, 1.0, 2.0)
const EVENT := PongServoFacts.PongEventType
const SURFACE := PongServoFacts.CourtSurface
const KIND := PongServoFacts.PongEffectKind

var door: HapticsTestKit.Door = null
var pong: PongServo = null


func before_each() -> void:
	door = autofree(HapticsTestKit.manual())
	pong = PongServo.new(door)
	assert_true(door.device.set_hand_target_3d(Vector3.ZERO))
	assert_true(pong.enter())


# Player 0 holds the device paddle flat, facing up, at AVATAR; player 1 is out of play.
func _flat_paddle(local_player: int = 0) -> PongInput:
	var input: PongInput = PongInput.new()
	input.local_player = local_player
	input.players[0].avatar = AVATAR
	input.players[0].normal = Vector3.UP
	input.players[1].avatar = Vector3(0.0, 1.0, -2.0)
	input.players[1].active = false
	return input


# Steps like a 60 Hz game at 1 kHz (the input is the watchdog's heartbeat); returns the
# events drained along the way.
func _play(input: PongInput, ticks: int) -> Array[PongEvent]:
	var events: Array[PongEvent] = []
	for tick: int in ticks:
		if tick % 16 == 0:
			assert_true(pong.set_input(input))
		assert_true(door.servo.step(PongServo.TICK_S))
		events.append_array(pong.drain_events())
	return events


# A command as the renderer takes it, past PongServo's own checks (which refuse before
# sending what the servo would refuse).
func _effect_command(player: int, kind: PongServoFacts.PongEffectKind) -> PongCommand:
	var command: PongCommand = PongCommand.new()
	command.type = PongServoFacts.PongCommandType.EFFECT
	command.player = player
	command.kind = kind
	return command


func _send(value: HapticsValue) -> bool:
	return door.renderer(PongServo.NAME).send(value)


func test_pong_is_a_renderer_by_name_with_its_own_settings() -> void:
	assert_true(pong.is_available())
	assert_true(pong.is_active())
	assert_eq(door.get_render_mode(), PongServo.NAME)
	var settings: PongSettings = pong.get_settings()
	assert_almost_eq(settings.contact_force_n, 1.6, 1e-9, "c = k_p d by default")
	settings.gravity_m_per_s2 = 0.0
	settings.spin_gain = 2000.0
	assert_true(pong.apply_settings(settings))
	assert_eq(pong.get_settings().gravity_m_per_s2, 0.0)
	settings.restitution_paddle = 1.5
	expect_error("PongSettings.restitution_paddle: 1.5 is outside [0, 1]")
	assert_false(pong.apply_settings(settings))
	assert_eq(pong.get_settings().restitution_paddle, PongSettings.new().restitution_paddle)
	pong.leave()
	assert_false(pong.is_active())
	assert_eq(door.get_render_mode(), &"movement", "leave() restores the renderer before")


func test_a_ball_landing_on_the_device_paddle_pushes_the_hand_down() -> void:
	assert_true(pong.set_ball(AVATAR + Vector3(0, 0.4, 0), Vector3.ZERO))
	var events: Array[PongEvent] = _play(_flat_paddle(), 1500)
	var state: PongState = pong.get_state()
	assert_true(state.in_contact[0], "the ball rests on the paddle")
	assert_almost_eq(state.paddle_normals[0], Vector3.UP, 1e-6)
	assert_gt(state.ball_position.y, AVATAR.y, "above the paddle")
	var contact: Vector3 = state.hand_force.contact
	assert_lt(contact.y, 0.0, "the ball presses the hand down, along the paddle normal")
	assert_almost_eq(Vector2(contact.x, contact.z), Vector2.ZERO, 1e-6)
	var felt: Vector2 = door.get_forces().parts[PongServoFacts.PongForce.CONTACT]
	assert_almost_eq(felt.y, -contact.y, 1e-5, "get_forces: game axes")
	assert_gt(state.paddle_contacts, 0)
	assert_gt(PongTestEvents.count(events, EVENT.PADDLE), 0)
	var touch: PongEvent = PongTestEvents.of_type(events, EVENT.PADDLE)[0]
	assert_eq(touch.player, 0)
	assert_eq(touch.back_wall_of, -1, "a paddle event names no wall")
	assert_eq(touch.wall, SURFACE.FLOOR, "(the field's default)")
	assert_gt(touch.speed, 1.0, "it fell 0.33 m onto the paddle")
	assert_false(door.servo.get_stats().watchdog_tripped)


func test_the_ball_flies_bounces_and_changes_territory() -> void:
	var input: PongInput = _flat_paddle()
	input.players[0].active = false
	assert_true(pong.set_ball(Vector3(0.3, 1.0, 1.0), Vector3(0.0, 0.0, -3.0)))
	var events: Array[PongEvent] = _play(input, 1200)
	assert_eq(PongTestEvents.count(events, EVENT.TERRITORY), 1)
	var crossing: PongEvent = PongTestEvents.of_type(events, EVENT.TERRITORY)[0]
	assert_eq(crossing.territory, 1)
	assert_eq(crossing.player, -1)
	assert_gt(PongTestEvents.count(events, EVENT.FLOOR), 0)
	var landing: PongEvent = PongTestEvents.of_type(events, EVENT.FLOOR)[0]
	assert_eq(landing.territory, 1, "it landed in player 1's half")
	assert_gt(landing.speed, 0.8)
	assert_gt(landing.time_s, 0.0)
	assert_lt(landing.position.z, 0.0, "on the far side")
	var state: PongState = pong.get_state()
	assert_eq(state.territory, 1)
	assert_gt(state.bounces, 0)
	assert_almost_eq(state.time_s, 1.2, 1e-6)
	assert_eq(state.events_dropped, 0)


func test_a_wall_bounce_names_the_wall() -> void:
	var input: PongInput = _flat_paddle()
	input.players[0].active = false
	input.beginner = true
	var height: float = pong.get_settings().beginner_height_m
	assert_true(pong.set_ball(Vector3(1.0, height, 0.5), Vector3(3.0, 0.0, 0.0)))
	var walls: Array[PongEvent] = PongTestEvents.of_type(_play(input, 300), EVENT.WALL)
	assert_gt(walls.size(), 0)
	assert_eq(walls[0].wall, SURFACE.RIGHT)
	assert_eq(walls[0].back_wall_of, -1, "a side wall is nobody's goal")
	assert_almost_eq(walls[0].position.y, height, 1e-6, "beginner mode holds its plane")


func test_effects_push_the_device_players_hand_in_its_own_device_space() -> void:
	var settings: PongSettings = pong.get_settings()
	var recoil_s: float = settings.recoil_duration_s
	var mine_s: float = settings.mine_effect_duration_s
	var strength: float = PongServo.DEFAULT_STRENGTH
	for local_player: int in [0, 1]:
		assert_true(pong.set_input(_flat_paddle(local_player)))
		assert_true(pong.apply_effect(local_player, "recoil", strength, recoil_s, Vector3.RIGHT))
		assert_true(door.servo.step(PongServo.TICK_S))
		var state: PongState = pong.get_state()
		# Player 1 faces the other way: world +x is its device -x.
		var expected: float = 1.2 if local_player == 0 else -1.2
		assert_almost_eq(state.hand_force.effects, Vector3(expected, 0.0, 0.0), 1e-6)
		assert_eq(state.effects.size(), 1)
		assert_eq(state.effects[0].kind, KIND.RECOIL)
		assert_lt(state.effects[0].remaining_s, 0.08)
		assert_eq(PongServo.effect_in(state, "recoil"), state.effects[0])
		assert_null(PongServo.effect_in(state, "heavy"))
		assert_true(pong.clear_effects())
		assert_true(door.servo.step(PongServo.TICK_S))
		assert_eq(pong.get_state().effects.size(), 0)
	assert_true(pong.apply_effect(1, "heavy", 0.5, 1.0))
	assert_true(pong.apply_effect(1, "none", strength, mine_s))
	_play(_flat_paddle(1), 500)
	assert_almost_eq(pong.get_state().hand_force.effects, Vector3(0.0, -0.5, 0.0), 1e-6)


func test_the_3d_hand_target_moves_the_paddle_in_depth() -> void:
	var scale: float = pong.get_settings().workspace_scale
	assert_true(pong.set_hand_target_3d(Vector3(0.0, 0.0, 0.04)))
	_play(_flat_paddle(), 500)
	var center: Vector3 = pong.get_state().paddle_centers[0]
	assert_almost_eq(center, AVATAR + Vector3(0.0, 0.0, 0.04 * scale), 1e-3)
	assert_almost_eq(door.device.get_hand_target(), Vector2.ZERO, 1e-9, "x and y in game axes")
	expect_error("hand_target: not finite")
	assert_false(door.device.set_hand_target_3d(Vector3(0.0, 0.0, NAN)))
	# Beyond the workspace the target is held at its radius.
	var radius: float = door.device.get_workspace_radius()
	assert_true(pong.set_hand_target_3d(Vector3(0.0, 0.0, 2.0)))
	_play(_flat_paddle(), 500)
	center = pong.get_state().paddle_centers[0]
	assert_almost_eq(center, AVATAR + Vector3(0.0, 0.0, radius * scale), 1e-3)


func test_bad_input_is_refused_by_field_and_changes_nothing() -> void:
	assert_true(pong.set_input(_flat_paddle()))
	assert_true(door.servo.step(PongServo.TICK_S))
	var before: PongState = pong.get_state()
	var bad: PongInput = _flat_paddle()
	bad.players[0].avatar = Vector3(NAN, 0.0, 0.0)
	expect_error("PongInput.players[0].avatar: not finite")
	assert_false(pong.set_input(bad))
	bad = _flat_paddle()
	bad.players[1].avatar = Vector3(2000.0, 0.0, 0.0)
	expect_error("PongInput.players[1].avatar: length 2000 is above 1000")
	assert_false(pong.set_input(bad))
	bad = _flat_paddle()
	bad.players.resize(1)
	expect_error("PongInput.players: 1 items, exactly 4")
	assert_false(pong.set_input(bad))
	bad = _flat_paddle()
	bad.players.append(PongPlayerInput.new())
	expect_error("PongInput.players: 5 items, exactly 4")
	assert_false(pong.set_input(bad))
	bad = _flat_paddle()
	bad.local_player = 7
	expect_error("PongInput.local_player: 7 is outside [-1, 3]")
	assert_false(pong.set_input(bad))
	assert_true(door.servo.step(PongServo.TICK_S))
	var after: PongState = pong.get_state()
	assert_eq(after.paddle_centers[0], before.paddle_centers[0], "the previous input stays")
	assert_eq(after.paddle_normals[0], before.paddle_normals[0])
	assert_eq(after.paddle_velocities[0], before.paddle_velocities[0])
	assert_eq(after.in_contact[0], before.in_contact[0])


func test_bad_commands_are_refused_by_field_and_queue_nothing() -> void:
	var serve: PongCommand = PongCommand.new()
	# One past the last value: what an older or newer script might send.
	var no_type: int = PongServoFacts.PONG_COMMAND_TYPE_NAMES.size()
	serve.type = no_type as PongServoFacts.PongCommandType
	expect_error("PongCommand.type: 4 is none of the 4 values")
	assert_false(_send(serve))
	expect_error("PongCommand.position (0, 1, 9) is outside the court")
	assert_false(pong.set_ball(Vector3(0, 1, 9), Vector3.ZERO))
	var no_kind: int = PongServoFacts.PONG_EFFECT_KIND_NAMES.size()
	var laser: PongCommand = _effect_command(0, no_kind as PongServoFacts.PongEffectKind)
	expect_error("PongCommand.kind: 6 is none of the 6 values")
	assert_false(_send(laser))
	expect_error("unknown kind 'laser' (one of none, recoil")
	assert_false(pong.apply_effect(0, "laser", PongServo.DEFAULT_STRENGTH, 1.0))
	expect_error("PongCommand.direction: zero length")
	assert_false(_send(_effect_command(0, KIND.HIT)))
	expect_error("a hit needs a direction")
	assert_false(pong.apply_effect(0, "hit", PongServo.DEFAULT_STRENGTH, 1.0))
	var remote: PongCommand = _effect_command(0, KIND.REMOTE)
	remote.owner = 0
	expect_error("PongCommand.owner must be another player")
	assert_false(_send(remote))
	expect_error("a remote effect's owner must be another player than 0")
	assert_false(pong.apply_effect(0, "remote", PongServo.DEFAULT_STRENGTH, 1.0, Vector3.ZERO, 0))
	var heavy: PongCommand = _effect_command(0, KIND.HEAVY)
	heavy.use_default_magnitude = false
	heavy.magnitude_n = -1.0
	expect_error("PongCommand.magnitude_n: -1 is outside [0, 100]")
	assert_false(_send(heavy))
	expect_error("PongCommand.player must be 0..1 on this court (got 2)")
	assert_false(_send(_effect_command(2, KIND.HEAVY)))
	var layout: String = "layout %08x" % PongState.SCHEMA_ID
	var takes: String = "PongInput, PongCommand, PongWitnessCheck, PongWitnessPose"
	expect_error(layout + " is none of the values this renderer takes (%s)" % takes)
	assert_false(_send(PongState.new()))
	assert_true(door.servo.step(PongServo.TICK_S))
	assert_eq(pong.get_state().effects.size(), 0, "nothing was queued")


func test_the_state_decodes_with_every_seat_and_the_far_paddle_faces_home() -> void:
	var input: PongInput = _flat_paddle()
	assert_eq(input.players[1].normal, Vector3.ZERO, "player 1 gives no normal")
	assert_true(pong.set_input(input))
	assert_true(door.servo.step(PongServo.TICK_S))
	var bytes: PackedByteArray = door.renderer(PongServo.NAME).read(PongState.SCHEMA_ID)
	var state: PongState = PongState.decode(bytes)
	if not assert_not_null(state, HapticsWireReader.last_error):
		return
	assert_eq(state.player_count, 2)
	assert_eq(state.paddle_centers.size(), PongServoFacts.PONG_MAX_PLAYERS)
	assert_eq(state.paddle_normals.size(), PongServoFacts.PONG_MAX_PLAYERS)
	assert_eq(state.paddle_velocities.size(), PongServoFacts.PONG_MAX_PLAYERS)
	assert_eq(state.in_contact.size(), PongServoFacts.PONG_MAX_PLAYERS)
	var facing: String = "a zero normal is the seat's own facing: toward player 0"
	assert_almost_eq(state.paddle_normals[1], Vector3(0, 0, 1), 1e-6, facing)
	assert_null(PongState.decode(bytes.slice(0, bytes.size() - 1)))
	assert_ne(HapticsWireReader.last_error, "", "a cut value says why")


func test_four_players_a_square_court_four_states_and_back_wall_owners() -> void:
	var settings: PongSettings = pong.get_settings()
	settings.players = 3
	expect_error("PongSettings.players")
	assert_false(pong.apply_settings(settings), "3 is not built")
	assert_eq(pong.get_settings().players, 2, "a refused count changes nothing")
	settings.players = 4
	settings.gravity_m_per_s2 = 0.0
	assert_true(pong.apply_settings(settings))
	assert_eq(pong.get_settings().players, 4)
	var input: PongInput = PongInput.new()
	input.local_player = -1
	for seat: int in PongServoFacts.PONG_MAX_PLAYERS:
		input.players[seat].avatar = Vector3(0.0, 1.0, 0.0)
		input.players[seat].active = false
	assert_true(pong.set_input(input))
	# Toward player 2's back wall (x = +L, the square court's "right"): beyond the 2-player
	# court's width, inside the square.
	var l: float = settings.court_half_length_m
	assert_true(pong.set_ball(Vector3(l - 0.5, 1.0, 0.2), Vector3.RIGHT * 3.0))
	var walls: Array[PongEvent] = PongTestEvents.of_type(_play(input, 400), EVENT.WALL)
	assert_eq(walls.size(), 1)
	assert_eq(walls[0].wall, SURFACE.RIGHT)
	assert_eq(walls[0].back_wall_of, 2, "the right wall is player 2's goal")
	assert_eq(walls[0].territory, 2)
	var state: PongState = pong.get_state()
	assert_eq(state.player_count, 4, "one paddle per player")
	assert_eq(state.territory, 2)
	# A remote player's sample age (the network's delay) is part of a player's input.
	input.players[3].pose_age_s = 0.12
	assert_true(pong.set_input(input))
	input.players[3].pose_age_s = -0.1
	expect_error("PongInput.players[3].pose_age_s: -0.1 is outside [0, 10]")
	assert_false(pong.set_input(input))
	expect_error("PongCommand.player: 4 is outside [0, 3]")
	assert_false(_send(_effect_command(4, KIND.HEAVY)))
	assert_true(pong.apply_effect(3, "heavy", PongServo.DEFAULT_STRENGTH, 1.0))
	settings.players = 2
	assert_true(pong.apply_settings(settings))
	assert_true(door.servo.step(PongServo.TICK_S))
	assert_eq(pong.get_state().player_count, 2)
