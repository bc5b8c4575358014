extends TestSuite
## The fixture of the lobby suites: a fresh lobby scene in the tree for each test, freed
## after it, and a port for hosting on this machine.

const LOBBY_SCENE: PackedScene = preload("res://game/pong/net/ui/pong_lobby.tscn")

var _lobby: PongLobby = null


func before_each() -> void:
	_lobby = LOBBY_SCENE.instantiate() as PongLobby
	add_child(_lobby)
	await get_tree().process_frame


func after_each() -> void:
	if is_instance_valid(_lobby):
		_lobby.queue_free()
	await get_tree().process_frame
	await get_tree().process_frame


func _port() -> int:
	return 47000 + randi() % 2000
