extends TestSuite
## Players who leave together, on a real ENet server on this machine's loopback: Godot reports
## them one at a time, and while the server answers the first departure (a lobby or match
## message to everyone left) the others are already gone underneath. A send to one of them
## was an engine error in a CI match ("Unable to send packet on channel 4, max channels: 0").

const CLIENTS: int = 3


func test_a_message_to_everyone_in_a_departure_skips_the_players_who_left_with_it() -> void:
	var server: ENetMultiplayerPeer = ENetMultiplayerPeer.new()
	server.set_bind_ip("127.0.0.1")
	var port: int = 0
	for attempt: int in 20:
		port = 20000 + randi() % 20000
		if server.create_server(port, CLIENTS + 1) == OK:
			break
	var api: SceneMultiplayer = SceneMultiplayer.new()
	api.server_relay = false  # As a session's (it would tell the others of each departure).
	api.multiplayer_peer = server
	var clients: Array[ENetMultiplayerPeer] = []
	for i: int in CLIENTS:
		var client: ENetMultiplayerPeer = ENetMultiplayerPeer.new()
		assert_eq(client.create_client("127.0.0.1", port), OK)
		clients.append(client)
	for frame: int in 2000:
		api.poll()
		for client: ENetMultiplayerPeer in clients:
			client.poll()
		if api.get_peers().size() == CLIENTS:
			break
		OS.delay_msec(2)
	assert_eq(api.get_peers().size(), CLIENTS, "every client connected")
	var connected: Array[int] = []
	for peer: int in api.get_peers():
		connected.append(peer)
	assert_true(connected.all(func(p: int) -> bool: return PongNetEnet.can_send(api, p)))

	# Each departure the server hears of: whom it could still send to, and a send to each.
	var reachable_in_departures: Array[int] = []
	var departures: Array[int] = []
	var on_left: Callable = func(gone: int) -> void:
		departures.append(gone)
		for peer: int in api.get_peers():
			if PongNetEnet.can_send(api, peer):
				reachable_in_departures.append(peer)
				api.send_bytes(PackedByteArray([1]), peer)
	api.peer_disconnected.connect(on_left)
	for client: ENetMultiplayerPeer in clients:
		client.close()
	OS.delay_msec(200)
	api.poll()
	assert_eq(departures.size(), CLIENTS, "the server heard every client leave in one poll")
	assert_eq(reachable_in_departures, [] as Array[int], "no departed client was sent to")
	assert_false(PongNetEnet.can_send(api, connected[0]), "a client gone is not sent to")
	api.peer_disconnected.disconnect(on_left)  # It holds the API: a cycle otherwise.
	api.multiplayer_peer = null
	server.close()
