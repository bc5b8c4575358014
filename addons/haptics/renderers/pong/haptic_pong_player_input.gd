class_name HapticPongPlayerInput
extends RefCounted
## One player's part of a [HapticPongInput]: where the avatar (the workspace centre) is,
## the paddle when the game moves it, and the paddle's modes. World vectors in metres, y up.

## The avatar, world metres.
var avatar: Vector3 = Vector3.ZERO
## The game moves this paddle (the offset and velocity below count); otherwise it is the
## device's.
var kinematic: bool = false
## Kinematic paddles: the paddle centre relative to the avatar, world metres.
var paddle_offset: Vector3 = Vector3.ZERO
## Kinematic paddles: the paddle centre's world velocity, m/s.
var paddle_velocity: Vector3 = Vector3.ZERO
## The paddle's unit normal (also the gun's axis), world.
var normal: Vector3 = Vector3.FORWARD
## Spin paddle on.
var spin: bool = false
## Paddle held as a gun (no ball contact).
var gun: bool = false
## False: the player is out of play (paused, or out of the match); the ball passes through.
var active: bool = true
## Kinematic paddles: how old the offset and velocity are, seconds; the servo carries the
## paddle on by its velocity over it.
var pose_age_s: float = 0.0


## The player's entry of [code]HapticsServer.set_pong_input[/code]'s [code]players[/code].
func to_dictionary() -> Dictionary:
	return {
		"avatar": avatar,
		"kinematic": kinematic,
		"paddle_offset": paddle_offset,
		"paddle_velocity": paddle_velocity,
		"normal": normal,
		"spin": spin,
		"gun": gun,
		"active": active,
		"pose_age_s": pose_age_s,
	}
