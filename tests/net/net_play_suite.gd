extends "res://tests/pong/pong_screen_suite.gd"
## The fixture of the play suites: one peer of a real stepped match (the host, seat 0; the
## client, peer 42, drives seat 1, whose paddle comes over the network) without sockets.
## Received messages are handed to the handlers with their sender's id; what this peer
## sends is recorded.

const PongTestScreen := preload("res://tests/pong/pong_test_screen.gd")
const HOST: int = 1
const CLIENT: int = 42


## A play node that records what it would send.
class RecordingPlay:
	extends PongNetPlay

	var sent: Array[Array] = []

	func send_all(method: StringName, args: Array) -> void:
		sent.append([method] + args)

	func sent_of(method: StringName) -> Array[Array]:
		var out: Array[Array] = []
		for entry: Array in sent:
			if entry[0] == method:
				out.append(entry)
		return out


var _play: RecordingPlay = null


func after_each() -> void:
	if _play != null and is_instance_valid(_play):
		_play.queue_free()
	_play = null
	await _free_pong()


## The host's play, begun; null (and a failure) without the Pong renderer.
func _open_play() -> RecordingPlay:
	if not assert_true(PongServo.shared().is_available(), "the extension has the Pong renderer"):
		return null
	_pong = PongTestScreen.stepped()
	add_child(_pong)
	var match_node: PongMatch = _pong.match_node
	var remote: PongNetRemotePlayer = PongNetRemotePlayer.new(1)
	remote.intent = match_node.controllers[1].intent
	match_node.controllers[1] = remote
	(match_node.controllers[0] as PongAi).use_weapons = false
	_play = RecordingPlay.new()
	_play.session = PongNetSession.new()
	add_child(_play)
	_play.add_child(_play.session)
	_play.begin(
		match_node,
		PongNetAuthority.new(HOST, PackedInt64Array([HOST, CLIENT])),
		PackedInt32Array([0])
	)
	return _play
