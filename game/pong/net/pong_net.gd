class_name PongNet
extends Node
## Networked Haptic Battle Pong on this machine: the session ([PongNetSession]), the lobby
## (names, seats, ready-up, start, rematch, leave) and the match ([PongNetPlay]). It lives
## at /root/PongNet on every peer, so its RPCs find the same node everywhere.
##
## The server (peer 1) keeps the lobby: it gives each joining player the first free seat,
## starts the match when every player is ready (a dedicated server: by itself; a hosting
## player: on Start), and drives empty seats and the seats of players who left with the
## computer player. A client that loses its server ends the match cleanly.

signal lobby_changed
## A line for the lobby's status (connection, refusal, who left).
signal status_changed(text: String)
signal match_started
## The match ended: [param winner] (-1: cut short, [param why] says why).
signal match_ended(winner: int, why: String)

const NODE_NAME: String = "PongNet"
const PONG_SCENE: PackedScene = preload("res://game/pong/ui/pong.tscn")

## Seats of a match (territories): 2, or 4 on a square court. The server's choice, set
## before [method host]; a client takes the server's from the lobby.
var seats: int = 2
var my_name: String = "Player"
## A dedicated server: it plays no seat and shows nothing.
var dedicated: bool = false
## The computer drives this peer's own paddle (headless test peers).
var autopilot: bool = false
## Step the servo here, paced by the wall clock (headless peers) instead of its thread.
var stepped: bool = false
var start_health: int = PongRules.DEFAULT_START_HEALTH
## Lobby, peer id -> {name, seat, ready}.
var players: Dictionary[int, Dictionary] = {}
## Set up by the caller before a match: a hook that chooses this peer's controller for its
## own seat (tests: a still device paddle). Callable(seat, match) -> PongController or null.
var local_controller_factory: Callable = Callable()

var session: PongNetSession = null
var play: PongNetPlay = null
var screen: PongScreen = null


func _init() -> void:
	# The winner screen pauses the tree; the connection must not stop for it.
	process_mode = Node.PROCESS_MODE_ALWAYS
	session = PongNetSession.new()
	session.name = "Session"
	add_child(session)
	play = PongNetPlay.new()
	play.name = "Play"
	play.session = session
	play.owners_changed.connect(seats_changed)
	add_child(play)
	session.connected.connect(_on_connected)
	session.failed.connect(func(reason: String) -> void: status_changed.emit(reason))
	session.peer_left.connect(_on_peer_left)
	session.server_lost.connect(_on_server_lost)


func _process(delta: float) -> void:
	if play.is_running():
		play.frame(delta)


## Hosts a game on [param port]; a player's host takes seat 0. "" or the error.
func host(port: int) -> String:
	var error: String = session.host(port, PongNetProtocol.ENET_SLOTS)
	if not error.is_empty():
		status_changed.emit(error)
		return error
	players.clear()
	if not PongNetProtocol.SEAT_COUNTS.has(seats):
		seats = PongNetProtocol.SEAT_COUNTS[0]
	if not dedicated:
		players[1] = {"name": my_name, "seat": 0, "ready": false}
	status_changed.emit("Hosting on port %d%s" % [port, " (dedicated server)" if dedicated else ""])
	lobby_changed.emit()
	return ""


## Joins [param address]:[param port]. "" or the error.
func join(address: String, port: int) -> String:
	players.clear()
	var error: String = session.join(address, port)
	status_changed.emit(error if not error.is_empty() else "Connecting to %s:%d" % [address, port])
	return error


## Leaves the lobby or the match.
func leave() -> void:
	_end_match(-1, "left")
	session.close()
	players.clear()
	lobby_changed.emit()


## Ready (or not) for the next match.
func set_ready(is_ready: bool) -> void:
	if session.is_server:
		_on_ready(1, is_ready)
	elif session.is_open() and multiplayer.get_peers().has(PongNetAuthority.SERVER_ID):
		_ready_up.rpc_id(PongNetAuthority.SERVER_ID, is_ready)


## Server: whether a match may start now (two players or more, all ready, none running).
func can_start() -> bool:
	if not session.is_server or play.is_running() or players.size() < 2:
		return false
	for entry: Dictionary in players.values():
		if not entry.get("ready", false):
			return false
	return true


## Server: starts the match (when [method can_start]).
func start_match() -> bool:
	if not can_start():
		return false
	var owners: PackedInt64Array = PackedInt64Array()
	owners.resize(seats)
	owners.fill(PongNetAuthority.SERVER_ID)
	for peer: int in players:
		owners[players[peer]["seat"]] = peer
	for peer: int in players:
		players[peer]["ready"] = false
	_start.rpc(owners, start_health)
	_begin(owners, start_health)
	return true


## This peer's id, 0 while not connected.
func my_id() -> int:
	if not is_inside_tree():
		return 0
	var peer: MultiplayerPeer = multiplayer.multiplayer_peer
	if not session.is_open() or peer == null:
		return 0
	if peer.get_connection_status() != MultiplayerPeer.CONNECTION_CONNECTED:
		return 0
	return multiplayer.get_unique_id()


## The seat of this peer (-1: none, e.g. a dedicated server).
func my_seat() -> int:
	var me: int = my_id()
	return players[me]["seat"] if players.has(me) else -1


## The owners changed (a peer left): take over its seats if we are the server.
func seats_changed() -> void:
	if play.match_node == null:
		return
	for seat: int in seats:
		_set_controller(seat)


func _on_connected() -> void:
	status_changed.emit("Connected; waiting for the host to start")
	_hello.rpc_id(1, my_name)


func _on_peer_left(peer: int) -> void:
	var entry: Dictionary = players.get(peer, {})
	var name_left: String = entry.get("name", "peer %d" % peer)
	players.erase(peer)
	status_changed.emit("%s left" % name_left)
	if session.is_server:
		# At the end of the frame: ENet empties every peer whose goodbye came in the same
		# poll at once but Godot reports them one by one, so a message to all sent from here
		# could go to a peer already gone ("Unable to send packet on channel 4, max
		# channels: 0" when the clients of a finished match quit together).
		_after_peer_left.call_deferred(peer)
	lobby_changed.emit()


func _after_peer_left(peer: int) -> void:
	if not session.is_server:
		return
	_broadcast_lobby()
	if play.is_running():
		play.take_over(peer)


func _on_server_lost() -> void:
	status_changed.emit("The server is gone (%s)" % session.lost_reason)
	if play.is_running():
		play.report.extra["server_lost"] = {
			"wall_s": PongNetReport.now(), "why": session.lost_reason
		}
	_end_match(-1, "server lost")
	players.clear()
	lobby_changed.emit()


func _begin(owners: PackedInt64Array, health: int) -> void:
	_end_match(-1, "restart")
	# A rematch started while this peer still shows the last winner screen.
	close_screen()
	get_tree().paused = false
	var me: int = multiplayer.get_unique_id()
	session.announce_stall()
	screen = PONG_SCENE.instantiate() as PongScreen
	screen.stepped = stepped
	screen.players = seats
	screen.start_health = health
	screen.process_mode = Node.PROCESS_MODE_PAUSABLE
	add_child(screen)
	var match_node: PongMatch = screen.match_node
	match_node.self_stepping = false
	match_node.auto_serve = false
	match_node.rules_from_events = false
	if not screen.start_match(PongMatch.Mode.DEMO, false):
		status_changed.emit("No Pong renderer: build the extension")
		return
	screen.hud.visible = not dedicated
	var authority: PongNetAuthority = PongNetAuthority.new(me, owners)
	play.stepped = stepped
	play.ball.stepped = stepped
	play.begin(match_node, authority, PackedInt32Array())
	play.finished.connect(_on_finished, CONNECT_ONE_SHOT)
	seats_changed()
	match_started.emit()


# Who drives [param seat] here: our player (device or computer), the computer for the
# server's seats, or the network.
func _set_controller(seat: int) -> void:
	var match_node: PongMatch = play.match_node
	var seat_owner: int = play.authority.owner_of(seat)
	var me: int = multiplayer.get_unique_id()
	var current: PongController = match_node.controllers[seat]
	var seats_here: PackedInt32Array = play.local_seats
	if seat_owner != me:
		if not current is PongNetRemotePlayer:
			var remote: PongNetRemotePlayer = PongNetRemotePlayer.new(seat)
			remote.intent = current.intent
			match_node.controllers[seat] = remote
		if seats_here.has(seat):
			seats_here.remove_at(seats_here.find(seat))
		return
	if not seats_here.has(seat):
		seats_here.append(seat)
	var mine: bool = players.has(me) and players[me]["seat"] == seat
	if mine and local_controller_factory.is_valid():
		var made: PongController = local_controller_factory.call(seat, match_node)
		if made != null:
			match_node.controllers[seat] = made
			return
	if current is PongAi and (autopilot or not mine):
		return
	var radius: float = Haptics.device.get_workspace_radius()
	if mine and not autopilot:
		var human: PongHumanPlayer = PongHumanPlayer.new(
			seat, PongHumanPlayer.Scheme.DEVICE, match_node.court, match_node.reach, radius
		)
		human.kinematic = true
		match_node.controllers[seat] = human
		return
	var ai: PongAi = PongAi.new(seat, match_node.court, match_node.reach, seat + 1)
	ai.intent = current.intent
	match_node.controllers[seat] = ai


func _on_finished(winner: int) -> void:
	_end_match(winner, "over")


func _end_match(winner: int, why: String) -> void:
	if not play.is_running():
		return
	play.end()
	match_ended.emit(winner, why)


## Removes the match's screen (back to the lobby).
func close_screen() -> void:
	if screen != null:
		screen.queue_free()
		screen = null


func _broadcast_lobby() -> void:
	var rows: Array = []
	for peer: int in players:
		var entry: Dictionary = players[peer]
		rows.append([peer, entry["name"], entry["seat"], entry["ready"]])
	if session.is_open():
		_lobby.rpc(rows, seats)
	lobby_changed.emit()


func _on_ready(peer: int, is_ready: Variant) -> void:
	if typeof(is_ready) != TYPE_BOOL or not players.has(peer):
		session.misbehaved(peer, "ready", "not a bool or not in the lobby")
		return
	players[peer]["ready"] = is_ready
	_broadcast_lobby()


func _free_seat() -> int:
	var taken: Array[int] = []
	for entry: Dictionary in players.values():
		taken.append(entry["seat"])
	for seat: int in seats:
		if not taken.has(seat):
			return seat
	return -1


# The lobby's messages take their arguments as a list, so a wrong count is one of our bad
# messages, not an engine error (PongNetProtocol.check_arity); [] when it is wrong.
func _args(args: Array, count: int, what: String) -> Array:
	var reason: String = PongNetProtocol.check_arity(args, count)
	if reason.is_empty():
		return args
	session.misbehaved(multiplayer.get_remote_sender_id(), what, reason)
	return []


@rpc("any_peer", "call_remote", "reliable", PongNetProtocol.CHANNEL_HANDSHAKE)
func _hello(...args: Array) -> void:
	var sender: int = multiplayer.get_remote_sender_id()
	var hello: Array = _args(args, 1, "hello")
	if not session.is_server or hello.is_empty():
		return
	var reason: String = PongNetProtocol.check_name(hello[0])
	if not reason.is_empty() or players.has(sender):
		session.misbehaved(sender, "hello", reason if not reason.is_empty() else "a second one")
		return
	var seat: int = _free_seat()
	if play.is_running() or seat < 0:
		session.refuse(sender, "a match is running" if play.is_running() else "the server is full")
		return
	var player_name: String = hello[0]
	players[sender] = {"name": player_name, "seat": seat, "ready": false}
	status_changed.emit("%s joined (seat %d)" % [player_name, seat])
	_broadcast_lobby()


@rpc("any_peer", "call_remote", "reliable", PongNetProtocol.CHANNEL_RELIABLE)
func _ready_up(...args: Array) -> void:
	var ready_args: Array = _args(args, 1, "ready")
	if session.is_server and not ready_args.is_empty():
		_on_ready(multiplayer.get_remote_sender_id(), ready_args[0])


@rpc("any_peer", "call_remote", "reliable", PongNetProtocol.CHANNEL_RELIABLE)
func _lobby(...args: Array) -> void:
	var sender: int = multiplayer.get_remote_sender_id()
	var lobby: Array = _args(args, 2, "lobby")
	if lobby.is_empty():
		return
	var reason: String = PongNetProtocol.check_lobby(lobby[0], lobby[1])
	if sender != PongNetAuthority.SERVER_ID:
		reason = "only the server sends it"
	if not reason.is_empty():
		session.misbehaved(sender, "lobby", reason)
		return
	var table: Dictionary[int, Dictionary] = {}
	var list: Array = lobby[0]
	for row: Array in list:
		table[row[0]] = {"name": row[1], "seat": row[2], "ready": row[3]}
	seats = lobby[1]
	players = table
	lobby_changed.emit()


@rpc("any_peer", "call_remote", "reliable", PongNetProtocol.CHANNEL_RELIABLE)
func _start(...args: Array) -> void:
	var sender: int = multiplayer.get_remote_sender_id()
	var start: Array = _args(args, 2, "start")
	if start.is_empty():
		return
	var reason: String = PongNetProtocol.check_int(start[1], 1, 999, "health")
	if sender != PongNetAuthority.SERVER_ID:
		reason = "only the server starts a match"
	var list: PackedInt64Array = PackedInt64Array()
	if typeof(start[0]) == TYPE_PACKED_INT64_ARRAY:
		list = start[0]
	if reason.is_empty() and list.size() != seats:
		reason = "owners is not %d peer ids" % seats
	if not reason.is_empty():
		session.misbehaved(sender, "start", reason)
		return
	var start_with: int = start[1]
	_begin(list, start_with)
