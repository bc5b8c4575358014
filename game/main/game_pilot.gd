class_name GamePilot
extends RefCounted
## Steers the player of a [Game] in place of the person at the keys, the gamepad or the haptic
## device: the game hands it the run ([method start]) and asks it every physics tick
## ([method steer]); the simulated device's hand follows the input it sets, and the goal ends
## the run without the goal screen (nobody is there to read it).
## [br][br]
## The game has none of its own: a person plays. Test and demonstration drivers
## ([code]tests/drivers/[/code]) extend it and set [member Game.pilot].


## What the HUD names as steering.
func get_label() -> String:
	return "pilot"


## The run of [param _game] starts: its level and player are ready.
func start(_game: Game) -> void:
	pass


## Sets [member Player.input_vector] of [param _game]'s player for one physics tick of
## [param _delta] seconds; false ends the run (the clock stops and the player lets go).
func steer(_game: Game, _delta: float) -> bool:
	return true
