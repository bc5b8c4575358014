class_name PongNetReconnect
extends RefCounted
## A client whose server has fallen silent in a match connects again and rejoins it
## ([PongNetRejoins]). After [constant PongNetProtocol.REJOIN_AFTER_S] of silence the old
## connection is dropped without a word to the server (which keeps the seat for it, the
## computer standing in) and the client joins the same address again with its identity. A
## refusal ("a match is running": the server still hears the old connection) or a join with
## no answer tries again until the seat's grace has passed; then the client gives the server
## up as it would have. Meanwhile the match's last picture stays on the screen.

## Seconds between two tries of a refused rejoin.
const RETRY_S: float = 1.0

var _net: PongNet = null
# The server this client joined ("": none).
var _address: String = ""
var _port: int = 0
# While reconnecting: until when (pulse clock) the server keeps the seat; else -INF.
var _until_s: float = -INF
# When a refused try is followed by the next (pulse clock); INF: none pending.
var _retry_at_s: float = INF


func _init(net: PongNet) -> void:
	_net = net
	net.session.failed.connect(_on_failed)
	net.match_started.connect(_on_started)


## This client joins [param address]:[param port]: a rejoin goes there again.
func server_at(address: String, port: int) -> void:
	_address = address
	_port = port


## Whether this client is reconnecting to rejoin its match.
func is_reconnecting() -> bool:
	return _until_s > -INF


## How long the seat is kept for this reconnecting client, seconds.
func seat_kept_s() -> float:
	return maxf(_until_s - PongNetPulse.now_s(), 0.0)


## The server has been silent since [param silent_since_s] (pulse clock) in a match: drop the
## old connection and join again, until the seat's grace counted from then has passed.
func start(silent_since_s: float) -> void:
	if is_reconnecting() or _address.is_empty() or _net.session.is_server:
		return
	_until_s = silent_since_s + PongNetProtocol.SEAT_GRACE_S
	var silence: float = PongNetPulse.now_s() - silent_since_s
	_net.say("No word from the server for %.0f s\nreconnecting" % silence)
	_net.play.end()
	_net.players.clear()  # The server's lobby follows the new connection.
	var enet: ENetMultiplayerPeer = _net.multiplayer.multiplayer_peer as ENetMultiplayerPeer
	if enet != null and enet.get_peer(PongNetAuthority.SERVER_ID) != null:
		# No goodbye: a server told we left would give the seat up at once.
		enet.get_peer(PongNetAuthority.SERVER_ID).reset()
	_try()


## One frame: the next try of a refused rejoin, or the end of the grace.
func frame() -> void:
	if not is_reconnecting():
		return
	var now: float = PongNetPulse.now_s()
	if now >= _until_s:
		_give_up()
	elif now >= _retry_at_s:
		_try()


## The player left: no more tries.
func cancel() -> void:
	_until_s = -INF
	_retry_at_s = INF


func _try() -> void:
	_retry_at_s = INF
	_net.session.join(_address, _port)


func _on_failed(_reason: String) -> void:
	if is_reconnecting():
		_retry_at_s = PongNetPulse.now_s() + RETRY_S


func _on_started() -> void:
	if is_reconnecting():
		_until_s = -INF
		_net.say("Back in the match")


func _give_up() -> void:
	_until_s = -INF
	var grace: float = PongNetProtocol.SEAT_GRACE_S
	_net.session.lose_server("no word from the server for %.0f s: your seat was given up" % grace)
	_net.match_ended.emit(-1, "server lost")
