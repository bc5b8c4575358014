class_name PongNetRejoins
extends RefCounted
## Rejoining a running match. Each client draws a secret [member identity] and presents it
## in its hello; the server remembers which peer presented which. A later hello with the
## identity of a player of the running match whose seats are kept for it (silent, within
## [constant PongNetProtocol.SEAT_GRACE_S]: a crashed game restarted, a laptop on another
## network) takes those seats over under its new connection: its row of the lobby, its seats,
## the match as it stands ([PongNetResume]), and the ball from the server's own copy. The old
## connection is dropped. Anyone else is still refused while a match runs, and a player who is
## still heard keeps its seat whoever presents its identity.

## This peer's identity: 128 random bits as hex (a client may be given one to keep across
## restarts, [code]--identity[/code]).
var identity: String = Crypto.new().generate_random_bytes(16).hex_encode()

var _net: PongNet = null
# Server: the identity each connected peer presented.
var _identities: Dictionary[int, String] = {}


func _init(net: PongNet) -> void:
	_net = net


## Server: [param peer] said hello with [param presented].
func note(peer: int, presented: String) -> void:
	if not presented.is_empty():
		_identities[peer] = presented


## Server: [param peer] is gone.
func forget(peer: int) -> void:
	_identities.erase(peer)


## Server: the silent peer of the running match whose kept seats [param presented]
## reclaims, or 0.
func kept_for(presented: String) -> int:
	if presented.is_empty() or not _net.play.is_running():
		return 0
	var kept: Array[int] = _net.play.authority.kept.values()
	for peer: int in _identities:
		if _identities[peer] == presented and kept.has(peer) and _net.players.has(peer):
			return peer
	return 0


## The identity kept in [param path], drawn and written there the first time (or when the
## file holds none): a game restarted after a crash presents the same one.
static func lasting(path: String) -> String:
	var file: FileAccess = FileAccess.open(path, FileAccess.READ)
	if file != null:
		var text: String = file.get_as_text().strip_edges()
		if PongNetProtocol.is_identity(text):
			return text
	var fresh: String = PongNetRejoins.new(null).identity
	file = FileAccess.open(path, FileAccess.WRITE)
	if file != null:
		file.store_string(fresh)
	return fresh


## Server: [param sender] takes over the seats kept for [param old]: the lobby first (the
## client learns its seat from it), then the match as it stands, then its seats and the
## ball for everyone; the old connection goes.
func reclaim(sender: int, old: int) -> void:
	var play: PongNetPlay = _net.play
	var entry: Dictionary = _net.players[old]
	entry["ready"] = false
	_net.players.erase(old)
	_net.players[sender] = entry
	_identities[sender] = _identities[old]
	_identities.erase(old)
	play.authority.rekey_kept(old, sender)
	_net.broadcast_lobby()
	var start: PongNetStartMessage = PongNetStartMessage.new()
	start.owners = play.authority.owners.duplicate()
	for seat: int in play.authority.kept:
		if play.authority.kept[seat] == sender:
			start.owners[seat] = sender
	PongNetResume.as_it_stands(play.match_node, start)
	_net.session.router.send_to(sender, start)
	var epoch: int = play.authority.epoch
	play.seats.give_back(sender)
	if play.authority.epoch == epoch:
		play.take_ball()  # The rejoined peer learns the epoch and the ball from it.
	_net.session.drop_now(old)
	_net.say("%s rejoined" % entry.get("name", "peer %d" % sender))
