extends "res://tests/net/lobby_suite.gd"
## The network lobby on one machine: hosting lists the host in seat 1, ready-up is shown,
## Start needs a second player and says at once that it starts the match, Leave closes the
## session, and a join to a port where nobody listens fails with a message (no hang).

## Runs scenes or processes for seconds: make check (--quick) leaves it out.
const SLOW := true


func test_hosting_lists_the_host_and_start_waits_for_a_second_player() -> void:
	var net: PongNet = _lobby.net
	assert_not_null(net)
	assert_eq(net.get_path(), NodePath("/root/" + PongNet.NODE_NAME), "same path on every peer")
	net.my_name = "Ada"
	assert_eq(net.host(_port()), "")
	assert_true(net.session.is_server)
	assert_eq(net.players.size(), 1)
	assert_eq(net.my_seat(), 0)
	assert_true(_lobby._players.text.contains("Seat 1: Ada"), _lobby._players.text)
	net.set_ready(true)
	assert_true(_lobby._players.text.contains("(ready)"), _lobby._players.text)
	assert_false(net.can_start(), "one player cannot start")
	assert_false(net.start_match())
	net.leave()
	assert_false(net.session.is_open())
	assert_eq(net.players.size(), 0)


func test_joining_nobody_fails_with_a_message_after_trying_again() -> void:
	var patience: float = PongNetProtocol.JOIN_PATIENCE_S + 10.0
	set_timeout(patience + 5.0)
	var net: PongNet = _lobby.net
	var failures: Array[String] = []
	var retries: Array[String] = []
	net.session.failed.connect(func(reason: String) -> void: failures.append(reason))
	net.session.retrying.connect(
		func(_attempt: int) -> void: retries.append(_lobby._status.text), CONNECT_DEFERRED
	)
	assert_eq(net.join("127.0.0.1", _port()), "")
	var waited: float = 0.0
	while failures.is_empty() and waited < patience:
		await get_tree().create_timer(0.1).timeout
		waited += 0.1
	assert_gt(retries.size(), 0, "it tried again")
	if not retries.is_empty():
		assert_true(retries[0].contains("trying again"), retries[0])
	assert_gt(waited, PongNetProtocol.JOIN_PATIENCE_S - 1.0, "for the whole patience")
	assert_eq(failures.size(), 1, "connection_failed came once, at the end")
	if failures.size() == 1:
		assert_true(failures[0].contains("no answer from the server"), failures[0])
	assert_true(_lobby._status.text.contains("no answer"), _lobby._status.text)
	assert_false(net.session.is_open())


func test_start_says_so_at_once_and_the_match_follows() -> void:
	var net: PongNet = _lobby.net
	assert_eq(net.host(_port()), "")
	net.set_ready(true)
	net.players[42] = {"name": "Bob", "seat": 1, "ready": true}
	_lobby._refresh()
	assert_false(_lobby._start_button.disabled, "two players, both ready")
	_lobby._start_button.pressed.emit()
	# Before any frame: the press shows, though loading the court stalls the next frames.
	assert_eq(_lobby._status.text, PongLobby.STARTING_TEXT)
	assert_true(_lobby._start_button.disabled, "no second press")
	assert_true(await wait_until(func() -> bool: return net.play.is_running(), 10.0))
	assert_false(_lobby.visible, "the match shows instead of the lobby")
	net.leave()
