extends Node
## A headless computer-vs-computer Haptic Battle Pong match with the servo stepped by the game
## (faster than real time), for `make pong-demo`: the real Pong screen in its Computer vs
## computer mode, started without its setup. Prints each player who is out, then the winner
## and the simulated against the wall seconds, and quits with 0; without the Pong renderer it
## prints why there is no match and quits with 1.
## [codeblock]
## tools/godot --headless --path . res://tests/drivers/pong_demo.tscn -- \
##     [--pong-health=N] [--pong-players=4]
## [/codeblock]
## [code]--pong-health=N[/code]: each player's health (default [constant HEALTH]);
## [code]--pong-players=4[/code]: four computers on the square court (default 2).

const PONG_SCENE: PackedScene = preload("res://game/pong/ui/pong.tscn")
## Health of each player: a short match.
const HEALTH: int = 15

var _pong: PongScreen = null


func _ready() -> void:
	var health: int = HEALTH
	var players: int = 2
	for arg: String in OS.get_cmdline_user_args():
		if arg.begins_with("--pong-health="):
			health = maxi(1, arg.get_slice("=", 1).to_int())
		elif arg.begins_with("--pong-players="):
			players = 4 if arg.get_slice("=", 1).to_int() == 4 else 2
	_pong = PONG_SCENE.instantiate() as PongScreen
	_pong.skip_setup = true
	_pong.mode = PongMatch.Mode.DEMO
	_pong.stepped = true
	_pong.start_health = health
	_pong.players = players
	print("Pong demo: %d computers, health %d, stepped servo" % [players, health])
	add_child(_pong)
	if not _pong.is_running():
		print(_pong.setup.get_message())
		CleanExit.quit(1)
		return
	_pong.match_node.player_out.connect(_on_player_out)
	_pong.match_node.match_over.connect(_on_match_over)


func _on_player_out(player: int) -> void:
	print("Pong: %s is out at %.1f s" % [_pong.player_name(player), _pong.match_node.now])


func _on_match_over(winner: int) -> void:
	var match_node: PongMatch = _pong.match_node
	var health: PackedStringArray = PackedStringArray()
	for player: int in match_node.court.players:
		health.append(str(match_node.rules.get_health(player)))
	print(
		(
			"Pong: %s wins, %d players, health %s, %.1f simulated s in %.1f wall s (%.1fx real time)"
			% [
				_pong.player_name(winner),
				health.size(),
				" : ".join(health),
				match_node.now,
				match_node.now / maxf(match_node.speed_ratio(), 1e-6),
				match_node.speed_ratio(),
			]
		)
	)
	CleanExit.quit(0)
