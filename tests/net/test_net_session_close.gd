extends TestSuite
## Closing a session is quiet: a host or a client closed twice, closed by the server going
## away, or freed while connected pushes no engine error (the runner fails a test on any,
## such as "Attempt to disconnect a nonexistent connection"), and leaves none of its
## handlers on the multiplayer API. The client lives under its own [SceneMultiplayer]
## (SceneTree.set_multiplayer), so both ends run in this one process.
## [br][br]
## The exported release server's "nonexistent connection ... callable: ''" lines at exit are
## not these handlers: Debian's 4.6.3 release template fails the engine's own C++
## disconnects (a Container's child, SceneMultiplayer's node cache) on every removal, in a
## bare project too; its debug template and the editor binary print nothing.

var _server_root: Node = null
var _client_root: Node = null


func before_each() -> void:
	_server_root = Node.new()
	_server_root.name = "ServerSide"
	_client_root = Node.new()
	_client_root.name = "ClientSide"
	add_child(_server_root)
	add_child(_client_root)
	get_tree().set_multiplayer(SceneMultiplayer.new(), _server_root.get_path())
	get_tree().set_multiplayer(SceneMultiplayer.new(), _client_root.get_path())


func after_each() -> void:
	for side_name: String in ["ServerSide", "ClientSide"]:
		get_tree().set_multiplayer(null, NodePath("%s/%s" % [get_path(), side_name]))
		var side: Node = get_node_or_null(side_name)
		if side != null:
			side.queue_free()
	await get_tree().process_frame


func _port() -> int:
	return 45000 + randi() % 2000


func _session(side: Node) -> PongNetSession:
	var session: PongNetSession = PongNetSession.new()
	side.add_child(session)
	return session


func _handlers_left(session: PongNetSession, api: SceneMultiplayer) -> int:
	var left: int = 0
	for connection: Dictionary in session.get_incoming_connections():
		var sig: Signal = connection["signal"]
		left += 1 if sig.get_object() == api else 0
	return left


func test_a_host_closed_twice_and_freed_is_quiet() -> void:
	var host: PongNetSession = _session(_server_root)
	var api: SceneMultiplayer = host.multiplayer as SceneMultiplayer
	assert_eq(host.host(_port(), 4), "")
	assert_true(host.is_open())
	assert_eq(_handlers_left(host, api), 7, "hosting connects its seven handlers")
	host.close()
	host.close()
	assert_false(host.is_open())
	assert_eq(_handlers_left(host, api), 0)
	assert_true(api.multiplayer_peer is OfflineMultiplayerPeer)
	host.free()
	await get_tree().process_frame


func test_a_client_that_lost_its_server_closes_quietly_again_and_on_free() -> void:
	set_timeout(40.0)
	var port: int = _port()
	var host: PongNetSession = _session(_server_root)
	var client: PongNetSession = _session(_client_root)
	var client_api: SceneMultiplayer = client.multiplayer as SceneMultiplayer
	assert_ne(client_api, host.multiplayer, "each side has its own API")
	var lost: Array[bool] = []
	client.server_lost.connect(func() -> void: lost.append(true))
	assert_eq(host.host(port, 4), "")
	assert_eq(client.join("127.0.0.1", port), "")
	var joined: bool = await wait_until(
		func() -> bool: return host.multiplayer.get_peers().size() == 1, 15.0
	)
	assert_true(joined, "the client joined within 15 s")
	host.close()
	var noticed: bool = await wait_until(func() -> bool: return not lost.is_empty(), 15.0)
	assert_true(noticed, "the client noticed the server leave within 15 s")
	assert_false(client.is_open())
	client.close()
	assert_eq(_handlers_left(client, client_api), 0)
	client.free()
	host.free()
	await get_tree().process_frame


func test_a_connected_client_freed_with_its_side_is_quiet() -> void:
	set_timeout(40.0)
	var port: int = _port()
	var host: PongNetSession = _session(_server_root)
	var client: PongNetSession = _session(_client_root)
	assert_eq(host.host(port, 4), "")
	assert_eq(client.join("127.0.0.1", port), "")
	var joined: bool = await wait_until(
		func() -> bool: return host.multiplayer.get_peers().size() == 1, 15.0
	)
	assert_true(joined, "the client joined within 15 s")
	# Its _exit_tree closes it while its API still exists; then the API goes too.
	_client_root.free()
	var gone: bool = await wait_until(
		func() -> bool: return host.multiplayer.get_peers().is_empty(), 15.0
	)
	assert_true(gone, "the server saw the client leave within 15 s")
	host.close()
