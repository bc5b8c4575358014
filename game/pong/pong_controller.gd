class_name PongController
extends RefCounted
## Whoever moves one player: the person at the device or the keyboard ([PongHumanPlayer])
## or the computer ([PongAi]). The match asks it for a [PongIntent] every update and tells
## it the servo's events; the match sets [member speed_factor] from the running effects.

## The player it moves (0 near, 1 far).
var player: int = 0
## Its decision, kept between updates (the avatar's position lives here).
var intent: PongIntent = PongIntent.new()
## Whether the game moves its paddle (false: the device does, in the servo).
var kinematic: bool = true
## Multiplies the speeds of its avatar and paddle (a slow mine lowers it).
var speed_factor: float = 1.0


## This update's decision, [param dt] seconds at time [param now], from the newest servo
## state; [param opponent_avatar] is where the other player stands.
func update(_now: float, _dt: float, _snapshot: PongState, _opponent_avatar: Vector3) -> PongIntent:
	return intent


## A servo event ([method PongServo.drain_events]), at time [param now].
func notice(_event: PongEvent, _now: float) -> void:
	pass


## An input event the screen did not use ([param viewport_size]: for the mouse).
func handle_input(_event: InputEvent, _viewport_size: Vector2) -> void:
	pass
