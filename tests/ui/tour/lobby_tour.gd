extends "res://tests/ui/tour/tour.gd"
## Saves PNGs of the network lobby under a real display, for looking at it (not a test:
## the runner skips this folder's files).
## [codeblock]
## DISPLAY=:N tools/godot --path . --rendering-driver opengl3 --audio-driver Dummy \
##     res://tests/ui/tour/lobby_tour.tscn -- --out=/tmp/lobby-shots
## [/codeblock]
## Shots: the lobby as it opens, then hosting a four-seat game (the host in seat 1,
## the open seats, the Start button).

const LOBBY_SCENE: PackedScene = preload("res://game/pong/net/ui/pong_lobby.tscn")


func _ready() -> void:
	out = "user://lobby-shots"
	super()


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
