class_name HapticPongInput
extends RefCounted
## One update's input to the Pong renderer ([code]Haptics.pong.set_input[/code]): every
## player's avatar and paddle, which player holds the device, and beginner mode.

## Beginner mode (no gravity on the ball, goals behind the players).
var beginner: bool = false
## The player on the device, or -1 when no paddle is the device's.
var local_player: int = -1
## One entry per player of the court, in seat order.
var players: Array[HapticPongPlayerInput] = []


## The dictionary [code]HapticsServer.set_pong_input[/code] takes.
func to_dictionary() -> Dictionary:
	return {
		"beginner": beginner,
		"local_player": local_player,
		"players":
		players.map(func(p: HapticPongPlayerInput) -> Dictionary: return p.to_dictionary()),
	}
