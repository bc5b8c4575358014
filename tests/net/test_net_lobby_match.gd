extends TestSuite
## A match started from the lobby is one between its people, seen from each one's own seat:
## not the computer's demo, each seat named by its player (ours marked), the camera behind
## our own seat, our avatar and paddle moved by our keys and mouse toward the sides we see,
## the other person's seat driven by the network. No sockets: this peer is the server (the
## offline peer's id, 1) with a second player, 42, in its lobby; what it sends goes nowhere.

const OTHER: int = 42

var _net: PongNet = null


func after_each() -> void:
	await _stop()


# Ends the match and frees the peer.
func _stop() -> void:
	Input.action_release(&"move_left")
	if _net != null and is_instance_valid(_net):
		_net.leave()
		_net.close_screen()
		_net.queue_free()
	_net = null
	await wait_process_frames(2)


## Starts a lobby match with this peer's player "Ada" in [param my_seat] and "Bob" in the
## other; the match's screen, or null (and a failure) without the Pong renderer.
func _start(my_seat: int) -> PongScreen:
	if not assert_true(PongServo.shared().is_available(), "the extension has the Pong renderer"):
		return null
	_net = PongNet.new()
	_net.stepped = true
	add_child(_net)
	_net.session.is_server = true
	_net.players[1] = {"name": "Ada", "seat": my_seat, "ready": true}
	_net.players[OTHER] = {"name": "Bob", "seat": 1 - my_seat, "ready": true}
	assert_true(_net.can_start(), "two players, both ready")
	assert_true(_net.start_match())
	assert_not_null(_net.screen, "the match's screen")
	return _net.screen


# Steps the match [param seconds] of simulated time.
func _step(seconds: float) -> void:
	_net.play.match_node.run_until(func() -> bool: return false, seconds)


# The camera's right, flat on the court.
func _screen_right(screen: PongScreen) -> Vector3:
	var right: Vector3 = screen.world.camera.global_transform.basis.x
	return Vector3(right.x, 0.0, right.z).normalized()


# A local UDP port with nothing behind it (bound, then closed).
func _port_nobody_answers() -> int:
	var probe: PacketPeerUDP = PacketPeerUDP.new()
	probe.bind(0, "127.0.0.1")
	var port: int = probe.get_local_port()
	probe.close()
	return port


func test_the_match_is_between_the_people_and_named_by_the_lobby() -> void:
	var screen: PongScreen = _start(0)
	if screen == null:
		return
	var match_node: PongMatch = screen.match_node
	assert_ne(match_node.mode, PongMatch.Mode.DEMO, "not the computer playing every side")
	assert_true(match_node.controllers[0] is PongHumanPlayer, "our seat is our player's")
	assert_true(match_node.controllers[1] is PongNetRemotePlayer, "Bob's comes over the network")
	for controller: PongController in match_node.controllers:
		assert_false(controller is PongAi, "no computer in a match of two people")
	assert_eq(screen.player_name(0), "Ada (you)")
	assert_eq(screen.player_name(1), "Bob")
	assert_true(screen.hud.visible)


func test_the_camera_and_the_keys_follow_our_own_seat() -> void:
	for seat: int in [0, 1]:
		var screen: PongScreen = _start(seat)
		if screen == null:
			return
		var match_node: PongMatch = screen.match_node
		var behind: Vector3 = -PongCourt.forward(seat)
		assert_gt(screen.world.camera.global_position.dot(behind), 0.0, "behind seat %d" % seat)
		assert_eq(screen.player_name(seat), "Ada (you)")
		assert_eq(screen.player_name(1 - seat), "Bob")
		_step(0.2)
		var before: Vector3 = match_node.avatar_of(seat)
		Input.action_press(&"move_left")
		_step(0.4)
		Input.action_release(&"move_left")
		var moved: Vector3 = match_node.avatar_of(seat) - before
		# Left as this window shows the court: against the camera's right.
		assert_lt(moved.dot(_screen_right(screen)), -0.2, "seat %d walked left: %s" % [seat, moved])
		await _stop()


func test_the_mouse_moves_our_paddle_toward_the_side_we_see() -> void:
	for seat: int in [0, 1]:
		var screen: PongScreen = _start(seat)
		if screen == null:
			return
		var match_node: PongMatch = screen.match_node
		var size: Vector2 = Vector2(1280.0, 720.0)
		var centre: InputEventMouseMotion = InputEventMouseMotion.new()
		centre.position = size * 0.5
		match_node.controllers[seat].handle_input(centre, size)
		_step(0.6)
		var before: Vector3 = match_node.snapshot.paddle_centers[seat]
		var right: InputEventMouseMotion = InputEventMouseMotion.new()
		right.position = size * 0.5 + Vector2(size.y * 0.2, 0.0)
		match_node.controllers[seat].handle_input(right, size)
		_step(0.6)
		var moved: Vector3 = match_node.snapshot.paddle_centers[seat] - before
		assert_gt(moved.dot(_screen_right(screen)), 0.05, "seat %d paddle: %s" % [seat, moved])
		await _stop()


func test_players_who_keep_the_default_name_get_distinct_ones() -> void:
	_net = PongNet.new()
	add_child(_net)
	_net.seats = 4
	_net.session.is_server = true
	_net.players[1] = {"name": "Host", "seat": 0, "ready": false}
	var lines: Array[String] = []
	_net.status_changed.connect(func(text: String) -> void: lines.append(text))
	for peer: int in [OTHER, OTHER + 1]:
		var hello: PongNetHelloMessage = PongNetHelloMessage.new()
		hello.name = "Guest"
		_net.session.router.receive(peer, hello.encode())
	assert_eq(_net.players[OTHER]["name"], "Guest")
	assert_eq(_net.players[OTHER + 1]["name"], "Guest 2")
	assert_eq(lines, ["Guest joined (seat 2)", "Guest 2 joined (seat 3)"] as Array[String])
	var long: String = "x".repeat(PongNetProtocol.MAX_NAME_LENGTH)
	_net.players[OTHER + 2] = {"name": long, "seat": 3, "ready": false}
	var again: String = PongNetNames.unique(long, _net.players)
	assert_eq(again.length(), PongNetProtocol.MAX_NAME_LENGTH, again)
	assert_true(again.ends_with(" 2"), again)


func test_a_silent_player_is_played_by_the_computer_and_takes_the_seat_back() -> void:
	var screen: PongScreen = _start(0)
	if screen == null:
		return
	var match_node: PongMatch = screen.match_node
	var lines: Array[String] = []
	_net.status_changed.connect(func(text: String) -> void: lines.append(text))
	var pulse: PongNetPulse = _net.session.pulse
	assert_true(pulse.keeps_seat.call(OTHER), "Bob holds a seat in a running match")
	assert_false(pulse.keeps_seat.call(OTHER + 1), "nobody else does")
	pulse.peer_absent.emit(OTHER, 1.1)
	assert_true(match_node.controllers[1] is PongAi, "the computer stands in for Bob")
	assert_eq(screen.player_name(1), "Bob (away)", "everyone sees whose seat it is")
	assert_eq(_net.play.authority.owners, PackedInt64Array([1, 1]))
	assert_true(lines[-1].begins_with("Bob has connection trouble"), lines[-1])
	assert_true(screen.hud.get_status_text().begins_with("Bob has connection trouble"))
	_step(0.5)
	pulse.peer_back.emit(OTHER, 4.0)
	assert_true(match_node.controllers[1] is PongNetRemotePlayer, "Bob plays his seat again")
	assert_eq(screen.player_name(1), "Bob")
	assert_eq(_net.play.authority.owners, PackedInt64Array([1, OTHER]))
	assert_eq(lines[-1], "Bob is back after 4.0 s")
	pulse.peer_absent.emit(OTHER, 1.1)
	_net.session.peer_left.emit(OTHER)  # Silent past the grace: the seat is given up.
	assert_eq(screen.player_name(1), "Computer", "the computer's for good")


func test_a_player_whose_server_is_silent_sees_the_trouble_until_it_is_back() -> void:
	var screen: PongScreen = _start(0)
	if screen == null:
		return
	_net.session.is_server = false  # From here on this peer plays as a server's client.
	var pulse: PongNetPulse = _net.session.pulse
	assert_true(pulse.keeps_seat.call(PongNetAuthority.SERVER_ID), "in a match: kept")
	pulse.peer_absent.emit(PongNetAuthority.SERVER_ID, 1.2)
	await wait_process_frames(2)
	var shown: String = screen.hud.get_status_text()
	var trouble: RegEx = RegEx.create_from_string(
		"^Connection trouble: no word for (\\d+) s\nYour seat is kept (\\d+) s more$"
	)
	var found: RegExMatch = trouble.search(shown)
	assert_not_null(found, shown)
	if found != null:
		var total: int = int(found.get_string(1)) + int(found.get_string(2))
		assert_almost_eq(float(total), PongNetProtocol.SEAT_GRACE_S, 1.0, "the seconds add up")
	pulse.peer_back.emit(PongNetAuthority.SERVER_ID, 2.5)
	await wait_process_frames(2)
	assert_eq(screen.hud.get_status_text(), "Connection back after 2.5 s")


func test_a_player_whose_server_is_silent_for_long_reconnects_and_may_leave_meanwhile() -> void:
	var screen: PongScreen = _start(0)
	if screen == null:
		return
	_net.session.is_server = false
	_net.reconnect.server_at("127.0.0.1", _port_nobody_answers())
	var silence: float = PongNetProtocol.REJOIN_AFTER_S + 0.5
	_net.session.pulse.peer_absent.emit(PongNetAuthority.SERVER_ID, silence)
	await wait_process_frames(2)
	assert_true(_net.reconnect.is_reconnecting(), "past the limit: joining again")
	assert_false(_net.play.is_running(), "the match waits for the new connection")
	assert_true(_net.session.is_open(), "a join under way")
	var shown: String = screen.hud.get_status_text()
	var notice: RegEx = RegEx.create_from_string(
		"^Reconnecting: no word for (\\d+) s\nYour seat is kept (\\d+) s more$"
	)
	var found: RegExMatch = notice.search(shown)
	assert_not_null(found, shown)
	if found != null:
		var total: int = int(found.get_string(1)) + int(found.get_string(2))
		assert_almost_eq(float(total), PongNetProtocol.SEAT_GRACE_S, 1.0, "the seconds add up")
	# The player goes back to the menu: no more tries.
	_net.leave()
	assert_false(_net.reconnect.is_reconnecting())
	await wait_seconds(PongNetReconnect.RETRY_S + 0.5)
	assert_false(_net.session.is_open(), "no join after leaving")


func test_a_guest_silent_in_the_lobby_keeps_its_seat_and_no_match_starts_without_it() -> void:
	# CI's person suite: a joining guest busy loading was silent 1.58 s and dropped.
	_net = PongNet.new()
	add_child(_net)
	_net.session.is_server = true
	_net.players[1] = {"name": "Ada", "seat": 0, "ready": true}
	_net.players[OTHER] = {"name": "Bo", "seat": 1, "ready": true}
	var lines: Array[String] = []
	_net.status_changed.connect(func(text: String) -> void: lines.append(text))
	var pulse: PongNetPulse = _net.session.pulse
	assert_true(pulse.keeps_seat.call(OTHER), "a lobby player keeps its seat while silent")
	assert_false(pulse.keeps_seat.call(OTHER + 1), "a stranger does not")
	var beat: PongNetHeartbeat = pulse.heartbeat
	beat.watch(OTHER, 0.0)
	beat.heard(OTHER, 1.0)
	beat.overdue(2.6, func(_p: int) -> float: return 1.5, pulse.keeps_seat)
	assert_true(beat.is_absent(OTHER), "absent, not gone")
	pulse.peer_absent.emit(OTHER, 1.6)
	assert_true(lines[-1].begins_with("Bo has connection trouble"), lines[-1])
	assert_eq(_net.players[OTHER]["seat"], 1, "the lobby still lists Bo in seat 2")
	assert_false(_net.can_start(), "no match starts while Bo is not heard")
	beat.heard(OTHER, 3.0)
	beat.returned()
	assert_true(_net.can_start(), "heard again: the match may start")
