extends TestSuite
## Haptic Battle Pong through the binding, stepped manually with the simulated device: the
## ball flies, bounces and meets the device paddle; state, events, input, commands and the
## 3D hand target behave as the class reference says; bad dictionaries are refused by key.

const AVATAR := Vector3(0.0, 1.0, 2.0)

var server: HapticsServer = null


func before_each() -> void:
	server = HapticsServer.new()
	assert_true(server.open_device(server.get_simulated_device_id()))
	assert_true(server.set_hand_target_3d(Vector3.ZERO))
	assert_true(server.set_render_mode(HapticsServer.RENDER_MODE_PONG))


func after_each() -> void:
	server.close_device()


# Player 0 holds the device paddle flat, facing up, at AVATAR; player 1 is out of play.
func _flat_paddle(local_player: int = 0) -> Dictionary:
	return {
		"local_player": local_player,
		"players":
		[
			{"avatar": AVATAR, "normal": Vector3.UP},
			{"avatar": Vector3(0.0, 1.0, -2.0), "active": false},
		],
	}


# Steps like a 60 Hz game at 1 kHz (the input is the watchdog's heartbeat); returns the
# events drained along the way.
func _play(input: Dictionary, ticks: int) -> Array:
	var events: Array = []
	for tick: int in ticks:
		if tick % 16 == 0:
			assert_true(server.set_pong_input(input))
		assert_true(server.step(0.001))
		events.append_array(server.drain_pong_events())
	return events


func _of_type(events: Array, type: String) -> Array:
	return events.filter(func(event: Dictionary) -> bool: return event["type"] == type)


func _count(events: Array, type: String) -> int:
	return _of_type(events, type).size()


func test_the_pong_renderer_is_the_third() -> void:
	assert_eq(HapticsServer.RENDER_MODE_PONG, 2)
	assert_eq(server.get_render_mode(), HapticsServer.RENDER_MODE_PONG)
	var config: Dictionary = server.get_config()
	assert_has(config, "pong")
	assert_almost_eq(config["pong"]["contact_force_n"], 1.6, 1e-9, "c = k_p d by default")
	assert_true(server.set_config("pong", {"gravity_m_per_s2": 0.0, "spin_gain": 2000.0}))
	assert_eq(server.get_config()["pong"]["gravity_m_per_s2"], 0.0)
	expect_error("pong.restitution_paddle must be in [0, 1] (got 1.5)")
	assert_false(server.set_config("pong", {"restitution_paddle": 1.5}))


func test_a_ball_landing_on_the_device_paddle_pushes_the_hand_down() -> void:
	assert_true(server.pong_command({"type": "set_ball", "position": AVATAR + Vector3(0, 0.4, 0)}))
	var events: Array = _play(_flat_paddle(), 1500)
	var state: Dictionary = server.get_pong_state()
	var paddle: Dictionary = state["players"][0]
	assert_true(paddle["in_contact"], "the ball rests on the paddle")
	assert_almost_eq(paddle["normal"], Vector3.UP, 1e-6)
	assert_gt(state["ball"]["position"].y, AVATAR.y, "above the paddle")
	var contact: Vector3 = state["hand_force"]["contact"]
	assert_lt(contact.y, 0.0, "the ball presses the hand down, along the paddle normal")
	assert_almost_eq(Vector2(contact.x, contact.z), Vector2.ZERO, 1e-6)
	assert_almost_eq(server.get_forces()["contact"].y, -contact.y, 1e-5, "get_forces: game axes")
	assert_gt(state["paddle_contacts"], 0)
	assert_gt(_count(events, "paddle"), 0)
	var touch: Dictionary = _of_type(events, "paddle")[0]
	assert_eq(touch["player"], 0)
	assert_eq(touch["wall"], "")
	assert_gt(touch["speed"], 1.0, "it fell 0.33 m onto the paddle")
	assert_false(server.get_stats()["watchdog_tripped"])


func test_the_ball_flies_bounces_and_changes_territory() -> void:
	var input: Dictionary = _flat_paddle()
	input["players"][0]["active"] = false
	assert_true(
		(
			server
			. pong_command(
				{
					"type": "set_ball",
					"position": Vector3(0.3, 1.0, 1.0),
					"velocity": Vector3(0.0, 0.0, -3.0),
				}
			)
		)
	)
	var events: Array = _play(input, 1200)
	assert_eq(_count(events, "territory"), 1)
	var crossing: Dictionary = _of_type(events, "territory")[0]
	assert_eq(crossing["territory"], 1)
	assert_eq(crossing["player"], -1)
	assert_gt(_count(events, "floor"), 0)
	var landing: Dictionary = _of_type(events, "floor")[0]
	assert_eq(landing["territory"], 1, "it landed in player 1's half")
	assert_gt(landing["speed"], 0.8)
	assert_typeof_event(landing)
	var state: Dictionary = server.get_pong_state()
	assert_eq(state["territory"], 1)
	assert_gt(state["bounces"], 0)
	assert_almost_eq(state["time_s"], 1.2, 1e-6)
	assert_eq(state["events_dropped"], 0)


func assert_typeof_event(event: Dictionary) -> void:
	assert_eq(typeof(event["time_s"]), TYPE_FLOAT)
	assert_eq(typeof(event["position"]), TYPE_VECTOR3)
	assert_eq(typeof(event["speed"]), TYPE_FLOAT)
	assert_eq(typeof(event["territory"]), TYPE_INT)
	assert_eq(typeof(event["player"]), TYPE_INT)
	assert_eq(typeof(event["wall"]), TYPE_STRING)


func test_a_wall_bounce_names_the_wall() -> void:
	var input: Dictionary = _flat_paddle()
	input["players"][0]["active"] = false
	input["beginner"] = true
	var height: float = server.get_config()["pong"]["beginner_height_m"]
	assert_true(
		(
			server
			. pong_command(
				{
					"type": "set_ball",
					"position": Vector3(1.0, height, 0.5),
					"velocity": Vector3(3.0, 0.0, 0.0),
				}
			)
		)
	)
	var walls: Array = _of_type(_play(input, 300), "wall")
	assert_gt(walls.size(), 0)
	assert_eq(walls[0]["wall"], "right")
	assert_almost_eq(walls[0]["position"].y, height, 1e-6, "beginner mode holds its plane")


func test_effects_push_the_device_players_hand_in_its_own_device_space() -> void:
	for local_player: int in [0, 1]:
		assert_true(server.set_pong_input(_flat_paddle(local_player)))
		assert_true(
			(
				server
				. pong_command(
					{
						"type": "effect",
						"player": local_player,
						"kind": "recoil",
						"direction": Vector3(1.0, 0.0, 0.0),
					}
				)
			)
		)
		assert_true(server.step(0.001))
		var state: Dictionary = server.get_pong_state()
		# Player 1 faces the other way: world +x is its device -x.
		var expected: float = 1.2 if local_player == 0 else -1.2
		assert_almost_eq(state["hand_force"]["effects"], Vector3(expected, 0.0, 0.0), 1e-6)
		var effects: Array = state["effects"]
		assert_eq(effects.size(), 1)
		assert_eq(effects[0]["kind"], "recoil")
		assert_lt(effects[0]["remaining_s"], 0.08)
		assert_true(server.pong_command({"type": "clear_effects"}))
		assert_true(server.step(0.001))
		effects = server.get_pong_state()["effects"]
		assert_eq(effects.size(), 0)
	assert_true(
		server.pong_command(
			{"type": "effect", "player": 1, "kind": "heavy", "magnitude_n": 0.5, "duration_s": 1.0}
		)
	)
	assert_true(server.pong_command({"type": "effect", "player": 1, "kind": "none"}))
	_play(_flat_paddle(1), 500)
	assert_almost_eq(
		server.get_pong_state()["hand_force"]["effects"], Vector3(0.0, -0.5, 0.0), 1e-6
	)


func test_the_3d_hand_target_moves_the_paddle_in_depth() -> void:
	var scale: float = server.get_config()["pong"]["workspace_scale"]
	assert_true(server.set_hand_target_3d(Vector3(0.0, 0.0, 0.04)))
	_play(_flat_paddle(), 500)
	var center: Vector3 = server.get_pong_state()["players"][0]["paddle_center"]
	assert_almost_eq(center, AVATAR + Vector3(0.0, 0.0, 0.04 * scale), 1e-3)
	assert_almost_eq(server.get_hand_target(), Vector2.ZERO, 1e-9, "x and y in game axes")
	expect_error("hand_target: |target| must be <= 1 m")
	assert_false(server.set_hand_target_3d(Vector3(0.0, 0.0, 2.0)))


func test_bad_dictionaries_are_refused_by_key_and_change_nothing() -> void:
	assert_true(server.set_pong_input(_flat_paddle()))
	assert_true(server.step(0.001))
	var before: Dictionary = server.get_pong_state()["players"][0]
	var bad: Dictionary = _flat_paddle()
	bad["players"][0]["normal"] = Vector2.UP
	expect_error("pong_input.players[0].normal: expected a Vector3, got Vector2")
	assert_false(server.set_pong_input(bad))
	bad = _flat_paddle()
	bad["players"][0]["avatar"] = Vector3(NAN, 0.0, 0.0)
	expect_error("pong_input.players[0].avatar: not finite")
	assert_false(server.set_pong_input(bad))
	bad = _flat_paddle()
	bad["players"][1]["normal"] = Vector3.ZERO
	expect_error("pong_input.players[1].normal: zero length")
	assert_false(server.set_pong_input(bad))
	expect_error("pong_input: unknown key 'player'")
	assert_false(server.set_pong_input({"player": 0}))
	expect_error("pong_input.players: 1 entries, expected 2 to 4")
	assert_false(server.set_pong_input({"players": [{}]}))
	expect_error("pong_input.players: 5 entries, expected 2 to 4")
	assert_false(server.set_pong_input({"players": [{}, {}, {}, {}, {}]}))
	expect_error("pong_input.local_player must be -1 or 0..3 (got 7)")
	assert_false(server.set_pong_input({"local_player": 7}))
	assert_true(server.step(0.001))
	assert_eq(server.get_pong_state()["players"][0], before, "the previous input stays")

	expect_error("pong_command.type must be one of")
	assert_false(server.pong_command({"type": "serve"}))
	expect_error("pong_command.position: missing (expected a Vector3)")
	assert_false(server.pong_command({"type": "set_ball"}))
	expect_error("pong_command.position (0, 1, 9) is outside the court")
	assert_false(server.pong_command({"type": "set_ball", "position": Vector3(0, 1, 9)}))
	expect_error('pong_command.kind must be one of "none", "recoil"')
	assert_false(server.pong_command({"type": "effect", "player": 0, "kind": "laser"}))
	expect_error("pong_command.direction: missing (expected a Vector3)")
	assert_false(server.pong_command({"type": "effect", "player": 0, "kind": "hit"}))
	expect_error("pong_command.owner must be another player")
	assert_false(server.pong_command({"type": "effect", "player": 0, "kind": "remote", "owner": 0}))
	expect_error("pong_command.magnitude_n: expected a number, got String")
	assert_false(
		server.pong_command({"type": "effect", "player": 0, "kind": "heavy", "magnitude_n": "x"})
	)
	expect_error("pong_command: unknown key 'speed'")
	assert_false(server.pong_command({"type": "clear_effects", "speed": 1.0}))
	assert_true(server.step(0.001))
	var effects: Array = server.get_pong_state()["effects"]
	assert_eq(effects.size(), 0, "nothing was queued")


func test_the_state_has_every_key_in_its_type() -> void:
	assert_true(server.step(0.001))
	var state: Dictionary = server.get_pong_state()
	for key: String in [
		"time_s",
		"ball",
		"territory",
		"players",
		"hand_force",
		"effects",
		"paddle_contacts",
		"bounces",
		"events_dropped",
	]:
		assert_has(state, key)
	var ball: Dictionary = state["ball"]
	assert_eq(ball.keys(), ["position", "velocity", "spin", "correction", "correction_step_max"])
	var players: Array = state["players"]
	assert_eq(players.size(), 2)
	var far: Dictionary = players[1]
	assert_eq(far.keys(), ["paddle_center", "normal", "paddle_velocity", "in_contact"])
	assert_almost_eq(far["normal"], Vector3(0, 0, 1), 1e-6, "toward player 0")
	var hand: Dictionary = state["hand_force"]
	assert_eq(hand.keys(), ["contact", "spin", "effects", "total"])
	assert_eq(typeof(state["hand_force"]["total"]), TYPE_VECTOR3)
	assert_eq(typeof(state["paddle_contacts"]), TYPE_INT)


func test_four_players_a_square_court_four_states_and_back_wall_owners() -> void:
	expect_error("pong.players must be 2")
	assert_false(server.set_config("pong", {"players": 3}), "3 is not built")
	assert_eq(server.get_config()["pong"]["players"], 2, "a refused count changes nothing")
	assert_true(server.set_config("pong", {"players": 4, "gravity_m_per_s2": 0.0}))
	assert_eq(server.get_config()["pong"]["players"], 4)
	var players: Array = []
	for seat: int in 4:
		players.append({"avatar": Vector3(0.0, 1.0, 0.0), "active": false})
	assert_true(server.set_pong_input({"local_player": -1, "players": players}))
	# Toward player 2's back wall (x = +L, the square court's "right"): beyond the 2-player
	# court's width, inside the square.
	var l: float = server.get_config()["pong"]["court_half_length_m"]
	assert_true(
		server.pong_command(
			{
				"type": "set_ball",
				"position": Vector3(l - 0.5, 1.0, 0.2),
				"velocity": Vector3.RIGHT * 3.0
			}
		)
	)
	var events: Array = _play({"local_player": -1, "players": players}, 400)
	var walls: Array = _of_type(events, "wall")
	assert_eq(walls.size(), 1)
	assert_eq(walls[0]["wall"], "right")
	assert_eq(walls[0]["back_wall_of"], 2, "the right wall is player 2's goal")
	assert_eq(walls[0]["territory"], 2)
	var state: Dictionary = server.get_pong_state()
	var paddles: Array = state["players"]
	assert_eq(paddles.size(), 4, "one paddle per player")
	assert_eq(state["territory"], 2)
	# A remote player's sample age (the network's delay) is part of a player's input.
	players[3]["pose_age_s"] = 0.12
	assert_true(server.set_pong_input({"local_player": -1, "players": players}))
	players[3]["pose_age_s"] = -0.1
	expect_error("pong_input.players[3].pose_age_s")
	assert_false(server.set_pong_input({"local_player": -1, "players": players}))
	# Two entries are still an input: seats 2 and 3 then have no paddle in play.
	assert_true(server.set_pong_input(_flat_paddle()))
	expect_error("pong_command.player must be 0..3 (got 4)")
	assert_false(server.pong_command({"type": "effect", "player": 4, "kind": "heavy"}))
	assert_true(server.set_config("pong", {"players": 2}))
	assert_true(server.step(0.001))
	paddles = server.get_pong_state()["players"]
	assert_eq(paddles.size(), 2)
