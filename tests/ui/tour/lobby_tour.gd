extends Node
## Saves PNGs of the network lobby under a real display, for looking at it (not a test:
## the runner skips this folder's files).
## [codeblock]
## DISPLAY=:N tools/godot --path . --rendering-driver opengl3 --audio-driver Dummy \
##     res://tests/ui/tour/lobby_tour.tscn -- --out=/tmp/lobby-shots
## [/codeblock]
## Shots: the lobby as it opens, then hosting a four-seat game (the host in seat 1,
## the open seats, the Start button).

const LOBBY_SCENE: PackedScene = preload("res://scenes/pong/net/pong_lobby.tscn")

var _out: String = "user://lobby-shots"


func _ready() -> void:
	for arg: String in OS.get_cmdline_user_args():
		if arg.begins_with("--out="):
			_out = arg.get_slice("=", 1)
	DirAccess.make_dir_recursive_absolute(_out)
	_tour.call_deferred()


func _tour() -> void:
	var lobby: PongLobby = LOBBY_SCENE.instantiate() as PongLobby
	add_child(lobby)
	await _shot("lobby_open")
	lobby.choose_seats(4)
	lobby.net.seats = lobby.chosen_seats()
	lobby.net.host(47000 + randi() % 2000)
	await _shot("lobby_hosting_four_seats")
	lobby.net.leave()
	get_tree().quit(0)


func _shot(shot_name: String) -> void:
	await get_tree().create_timer(0.5, true).timeout
	for i: int in 2:
		await get_tree().process_frame
	await RenderingServer.frame_post_draw
	var path: String = "%s/%s.png" % [_out, shot_name]
	get_viewport().get_texture().get_image().save_png(path)
	print("saved %s" % path)
