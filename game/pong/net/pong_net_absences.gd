class_name PongNetAbsences
extends RefCounted
## Players silent in a match or in the lobby (a Wi-Fi hiccup, a tunnel, a machine busy
## loading): the seat stays theirs for [constant PongNetProtocol.SEAT_GRACE_S]. In a match,
## on the server the computer stands in from the heartbeat's limit on and gives the seat back
## when the player is heard again (in the lobby no match starts without them); the player
## sees "connection trouble" while it lasts. Only after the grace is the seat given up, and
## both sides say so.

var _net: PongNet = null
# A client: when its server fell silent in a match (pulse clock), INF while it is heard.
var _trouble_since_s: float = INF


func _init(net: PongNet) -> void:
	_net = net
	var pulse: PongNetPulse = net.session.pulse
	pulse.keeps_seat = _keeps_seat
	pulse.peer_absent.connect(_on_peer_absent)
	pulse.peer_back.connect(_on_peer_back)
	pulse.peer_lost.connect(_on_peer_lost)
	# A rejoined match starts on a new connection, whose server was never silent.
	net.match_started.connect(func() -> void: _trouble_since_s = INF)


## One frame: a client silent for long reconnects; the trouble on the screen, with how long
## the seat is kept.
func frame() -> void:
	var reconnect: PongNetReconnect = _net.reconnect
	reconnect.frame()
	var silence: float = PongNetPulse.now_s() - _trouble_since_s
	var troubled: bool = _net.play.is_running() and is_finite(_trouble_since_s)
	if troubled and silence >= PongNetProtocol.REJOIN_AFTER_S:
		reconnect.start(_trouble_since_s)
	if _net.screen == null:
		return
	var notice: String = ""
	# Two short lines: the status line sits between the players' panels.
	if reconnect.is_reconnecting():
		notice = (
			"Reconnecting: no word for %.0f s\nYour seat is kept %.0f s more"
			% [silence, reconnect.seat_kept_s()]
		)
	elif troubled:
		var left: float = maxf(PongNetProtocol.SEAT_GRACE_S - silence, 0.0)
		notice = (
			"Connection trouble: no word for %.0f s\nYour seat is kept %.0f s more"
			% [silence, left]
		)
	_net.screen.hud.notice = notice


# A silent peer keeps its seat: a client its server; the server a player of the match, or
# of the lobby (a joining guest's machine busy loading was dropped after 1.6 s in CI).
func _keeps_seat(peer: int) -> bool:
	if not _net.session.is_server:
		return true
	if _net.play.is_running():
		return _net.play.authority.owners.has(peer)
	return _net.players.has(peer)


func _on_peer_absent(peer: int, silence_s: float) -> void:
	if not _net.session.is_server:
		_trouble_since_s = PongNetPulse.now_s() - silence_s
		_net.status_changed.emit(
			"Connection trouble: no word from the server for %.1f s" % silence_s
		)
		return
	var grace: float = PongNetProtocol.SEAT_GRACE_S
	if not _net.play.is_running():
		_net.say(
			"%s has connection trouble\ntheir seat is kept up to %.0f s" % [_name_of(peer), grace]
		)
		return
	_net.say(
		(
			"%s has connection trouble\nthe computer plays for them up to %.0f s"
			% [_name_of(peer), grace]
		)
	)
	_net.play.seats.stand_in(peer)


func _on_peer_back(peer: int, silence_s: float) -> void:
	if not _net.session.is_server:
		_trouble_since_s = INF
		_net.say("Connection back after %.1f s" % silence_s)
		return
	_net.say("%s is back after %.1f s" % [_name_of(peer), silence_s])
	if _net.play.is_running():
		_net.play.seats.give_back(peer)


func _on_peer_lost(peer: int, silence_s: float) -> void:
	_trouble_since_s = INF
	if _net.session.is_server and silence_s > PongNetProtocol.SEAT_GRACE_S:
		_net.say("No word from %s for %.0f s\ntheir seat is given up" % [_name_of(peer), silence_s])


func _name_of(peer: int) -> String:
	var entry: Dictionary = _net.players.get(peer, {})
	return entry.get("name", "peer %d" % peer)
