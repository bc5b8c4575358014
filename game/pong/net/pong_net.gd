class_name PongNet
extends Node
## Networked Haptic Battle Pong on this machine: the session ([PongNetSession]), the lobby
## (names, seats, ready-up, start, rematch, leave) and the match ([PongNetPlay]). It lives
## at /root/PongNet on every peer. The lobby's messages ([PongNetHelloMessage],
## [PongNetReadyMessage], [PongNetLobbyMessage], [PongNetStartMessage]) come and go through
## the session's [PongNetRouter], which has checked their fields; this node checks them
## against the lobby.
##
## The server (peer 1) keeps the lobby: it gives each joining player the first free seat,
## starts the match when every player is ready (a dedicated server: by itself; a hosting
## player: on Start), and drives empty seats and the seats of players who left with the
## computer player. A client whose server falls silent in a match joins again and takes the
## seat back while it is kept ([PongNetReconnect], [PongNetRejoins]); one that loses its
## server ends the match cleanly.

signal lobby_changed
## A line for the lobby's status (connection, refusal, who left).
signal status_changed(text: String)
signal match_started
## The match ended: [param winner] (-1: cut short, [param why] says why).
signal match_ended(winner: int, why: String)

const NODE_NAME: String = "PongNet"
const PONG_SCENE: PackedScene = preload("res://game/pong/ui/pong.tscn")

## Seats (territories): 2, or 4 on a square court; set before [method host], else the lobby's.
var seats: int = 2
var my_name: String = "Player"
## A dedicated server: it plays no seat and shows nothing.
var dedicated: bool = false
## The computer drives this peer's own paddle (headless test peers).
var autopilot: bool = false
## Step the servo here, paced by the wall clock (headless peers) instead of its thread.
var stepped: bool = false
## Whether the match's screen draws its view and HUD (false: a headless peer, seen by nobody).
var draws_screen: bool = true
var start_health: int = PongRules.DEFAULT_START_HEALTH
## Lobby, peer id -> {name, seat, ready}.
var players: Dictionary[int, Dictionary] = {}
## Set up by the caller before a match: a hook that chooses this peer's controller for its
## own seat (tests: a still device paddle). Callable(seat, match) -> PongController or null.
var local_controller_factory: Callable = Callable()

var session: PongNetSession = null
var play: PongNetPlay = null
var screen: PongScreen = null
## This peer's identity, and on the server who presented which (a rejoin reclaims a seat).
var rejoins: PongNetRejoins = null
## A client's own rejoin when its server falls silent in a match.
var reconnect: PongNetReconnect = null

# Players silent for a while: their seats kept, the trouble shown.
var _absences: PongNetAbsences = null


func _init() -> void:
	# The winner screen pauses the tree; the connection must not stop for it.
	process_mode = Node.PROCESS_MODE_ALWAYS
	session = PongNetSession.new()
	session.name = "Session"
	add_child(session)
	play = PongNetPlay.new()
	play.name = "Play"
	play.session = session
	play.seats.changed.connect(seats_changed)
	add_child(play)
	rejoins = PongNetRejoins.new(self)
	reconnect = PongNetReconnect.new(self)
	session.connected.connect(_on_connected)
	# Deferred: the session closes right after it fails, and the lobby shows it closed.
	session.failed.connect(status_changed.emit, CONNECT_DEFERRED)
	session.peer_left.connect(_on_peer_left)
	session.server_lost.connect(_on_server_lost)
	session.retrying.connect(
		func(attempt: int) -> void:
			status_changed.emit("No answer from the server yet: trying again (try %d)" % attempt)
	)
	_absences = PongNetAbsences.new(self)
	var router: PongNetRouter = session.router
	router.handle(PongNetHelloMessage.SCHEMA_ID, _on_hello)
	router.handle(PongNetReadyMessage.SCHEMA_ID, _on_ready_message)
	router.handle(PongNetLobbyMessage.SCHEMA_ID, _on_lobby)
	router.handle(PongNetStartMessage.SCHEMA_ID, _on_start)


func _process(delta: float) -> void:
	if play.is_running():
		play.frame(delta)
	_absences.frame()


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
	reconnect.server_at(address, port)
	var error: String = session.join(address, port)
	status_changed.emit(error if not error.is_empty() else "Connecting to %s:%d" % [address, port])
	return error


## Leaves the lobby or the match (a rejoin under way too).
func leave() -> void:
	reconnect.cancel()
	_end_match(-1, "left")
	session.close()
	players.clear()
	lobby_changed.emit()


## Ready (or not) for the next match.
func set_ready(is_ready: bool) -> void:
	if session.is_server:
		_on_ready(1, is_ready)
	else:
		var message: PongNetReadyMessage = PongNetReadyMessage.new()
		message.ready = is_ready
		session.router.send_to(PongNetAuthority.SERVER_ID, message)


## Server: whether a match may start now (two players or more, all ready and heard, none
## running).
func can_start() -> bool:
	if not session.is_server or play.is_running() or players.size() < 2:
		return false
	for peer: int in players:
		if not players[peer].get("ready", false) or session.pulse.heartbeat.is_absent(peer):
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
	var start: PongNetStartMessage = PongNetStartMessage.new()
	start.owners = owners
	start.health = start_health
	session.router.send_all(start)
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
		var seat_owner: int = play.authority.owner_of(seat)
		var me: int = multiplayer.get_unique_id()
		var title: String = PongNetNames.seat_title(players, seats, seat, seat_owner, me)
		if screen != null and screen.player_name(seat) != title:
			screen.rename_player(seat, title)


func _on_connected() -> void:
	status_changed.emit("Connected; waiting for the host to start")
	var hello: PongNetHelloMessage = PongNetHelloMessage.new()
	hello.name = my_name
	hello.identity = rejoins.identity
	session.router.send_to(PongNetAuthority.SERVER_ID, hello)


func _on_peer_left(peer: int) -> void:
	rejoins.forget(peer)
	if players.has(peer):  # Not a connection a rejoin replaced.
		status_changed.emit("%s left" % players[peer]["name"])
	players.erase(peer)
	seats_changed()
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
	broadcast_lobby()
	if play.is_running():
		play.seats.take_over(peer)


## [param text] on the screen's status line in a match, and on the lobby's, its lines
## joined.
func say(text: String) -> void:
	status_changed.emit(text.replace("\n", ": "))
	if screen != null:
		screen.hud.flash(text)


func _on_server_lost() -> void:
	status_changed.emit("The server is gone (%s)" % session.lost_reason)
	_end_match(-1, "server lost")
	players.clear()
	lobby_changed.emit()


# [param resumed]: the server's start for a player who rejoins the running match.
func _begin(owners: PackedInt64Array, health: int, resumed: PongNetStartMessage = null) -> void:
	_end_match(-1, "restart")
	# A rematch started while this peer still shows the last winner screen.
	close_screen()
	get_tree().paused = false
	var me: int = multiplayer.get_unique_id()
	var seat_here: int = players[me]["seat"] if players.has(me) else -1
	var person_here: bool = seat_here >= 0 and not autopilot and not dedicated
	session.announce_stall()
	screen = PONG_SCENE.instantiate() as PongScreen
	screen.stepped = stepped
	screen.drawn = draws_screen
	screen.players = seats
	screen.start_health = health
	screen.viewer_seat = maxi(seat_here, 0)
	for seat: int in seats:
		screen.seat_names[seat] = PongNetNames.seat_title(players, seats, seat, owners[seat], me)
	screen.process_mode = Node.PROCESS_MODE_PAUSABLE
	add_child(screen)
	var match_node: PongMatch = screen.match_node
	match_node.self_stepping = false
	match_node.auto_serve = false
	match_node.rules_from_events = false
	# A person plays here against people: the computer only plays the seats nobody took.
	var mode: PongMatch.Mode = PongMatch.Mode.VS_COMPUTER if person_here else PongMatch.Mode.DEMO
	if not screen.start_match(mode, false):
		status_changed.emit("No Pong renderer: build the extension")
		return
	screen.hud.visible = not dedicated
	var authority: PongNetAuthority = PongNetAuthority.new(me, owners)
	play.stepped = stepped
	play.ball.stepped = stepped
	play.begin(match_node, authority, PackedInt32Array())
	if resumed != null:
		PongNetResume.take_up(play, resumed)
	if not play.finished.is_connected(_on_finished):  # A match cut short left it connected.
		play.finished.connect(_on_finished, CONNECT_ONE_SHOT)
	seats_changed()
	match_started.emit()


# Who drives [param seat] here (see [method PongNetControllers.assign]).
func _set_controller(seat: int) -> void:
	var me: int = multiplayer.get_unique_id()
	var mine: bool = players.has(me) and players[me]["seat"] == seat
	var factory: Callable = local_controller_factory
	PongNetControllers.assign(play, seat, me, mine, autopilot, factory)


func _on_finished(winner: int) -> void:
	_end_match(winner, "over")


func _end_match(winner: int, why: String) -> void:
	if not play.is_running():
		return
	play.end()
	match_ended.emit(winner, why)


## Removes the match's screen at once (its servo link leaves before a new screen's enters).
func close_screen() -> void:
	if screen != null:
		remove_child(screen)
		screen.queue_free()
		screen = null


func broadcast_lobby() -> void:
	var lobby: PongNetLobbyMessage = PongNetLobbyMessage.new()
	lobby.seats = seats
	for peer: int in players:
		var row: PongNetLobbyRow = PongNetLobbyRow.new()
		row.peer = peer
		row.name = players[peer]["name"]
		row.seat = players[peer]["seat"]
		row.ready = players[peer]["ready"]
		lobby.rows.append(row)
	session.router.send_all(lobby)
	lobby_changed.emit()


func _on_ready(peer: int, is_ready: bool) -> void:
	if not players.has(peer):
		session.misbehaved(peer, PongNetReadyMessage.LABEL, "not in the lobby")
		return
	players[peer]["ready"] = is_ready
	broadcast_lobby()


func _free_seat() -> int:
	var taken: Array[int] = []
	for entry: Dictionary in players.values():
		taken.append(entry["seat"])
	for seat: int in seats:
		if not taken.has(seat):
			return seat
	return -1


# --- received, their fields checked (PongNetRouter): the checks against the lobby ---


func _on_hello(sender: int, hello: PongNetHelloMessage) -> void:
	var reason: String = PongNetProtocol.check_name(hello.name)
	if reason.is_empty() and players.has(sender):
		reason = "a second one"
	if not reason.is_empty():
		session.misbehaved(sender, PongNetHelloMessage.LABEL, reason)
		return
	var old: int = rejoins.kept_for(hello.identity)
	if old != 0:
		rejoins.reclaim(sender, old)
		return
	var seat: int = _free_seat()
	if play.is_running() or seat < 0:
		session.refuse(sender, "a match is running" if play.is_running() else "the server is full")
		return
	rejoins.note(sender, hello.identity)
	var unique: String = PongNetNames.unique(hello.name, players)
	players[sender] = {"name": unique, "seat": seat, "ready": false}
	status_changed.emit("%s joined (seat %d)" % [unique, seat + 1])
	broadcast_lobby()


func _on_ready_message(sender: int, message: PongNetReadyMessage) -> void:
	_on_ready(sender, message.ready)


func _on_lobby(sender: int, lobby: PongNetLobbyMessage) -> void:
	var reason: String = ""
	if not PongNetProtocol.SEAT_COUNTS.has(lobby.seats):
		reason = "%d seats" % lobby.seats
	var table: Dictionary[int, Dictionary] = {}
	for row: PongNetLobbyRow in lobby.rows:
		if reason.is_empty() and row.seat >= lobby.seats:
			reason = "a row with seat %d of %d" % [row.seat, lobby.seats]
		table[row.peer] = {"name": row.name, "seat": row.seat, "ready": row.ready}
	if not reason.is_empty():
		session.misbehaved(sender, PongNetLobbyMessage.LABEL, reason)
		return
	seats = lobby.seats
	for peer: int in players:
		if not table.has(peer):  # Another client: the server's lobby is all we hear of it.
			status_changed.emit("%s left" % players[peer].get("name", "peer %d" % peer))
	players = table
	lobby_changed.emit()
	seats_changed()  # A player's seat given up in a match: its title says so.


func _on_start(sender: int, start: PongNetStartMessage) -> void:
	var reason: String = PongNetResume.check(start, seats)
	if not reason.is_empty():
		session.misbehaved(sender, PongNetStartMessage.LABEL, reason)
		return
	_begin(start.owners, start.health, start)
