class_name PongIntent
extends RefCounted
## What one player does this update, whoever decides it (the person at the device, the
## keyboard player, the computer): where the avatar is, the paddle (for a kinematic
## paddle), the modes, and the one-shot actions. The match turns it into the player's
## part of the servo's input ([method to_input]).

## The avatar (the workspace centre), world metres.
var avatar: Vector3 = Vector3.ZERO
## Kinematic paddles only: the paddle centre relative to the avatar, world metres.
var paddle_offset: Vector3 = Vector3.ZERO
## Kinematic paddles only: the paddle centre's world velocity, m/s.
var paddle_velocity: Vector3 = Vector3.ZERO
## The paddle's unit normal (also the gun's axis), world.
var normal: Vector3 = Vector3.FORWARD
## Spin paddle on.
var spin: bool = false
## Paddle held as a gun (no ball contact).
var gun: bool = false
## Fire a bullet this update (in gun mode).
var fire: bool = false
## Place a mine this update.
var place_mine: bool = false
## Kinematic paddles only: how old [member paddle_offset] and [member paddle_velocity] are,
## seconds (a remote player's pose, over the network); the servo carries the paddle on by
## its velocity over it, and the remote-operation mine's target too.
var pose_age_s: float = 0.0


## The player's entry of the servo's input: [param kinematic] when the game moves the
## paddle (the offset and velocity are then sent).
func to_input(kinematic: bool) -> PongPlayerInput:
	var entry: PongPlayerInput = PongPlayerInput.new()
	entry.avatar = avatar
	entry.kinematic = kinematic
	if kinematic:
		entry.paddle_offset = paddle_offset
		entry.paddle_velocity = paddle_velocity
		entry.pose_age_s = pose_age_s
	entry.normal = normal
	entry.spin = spin
	entry.gun = gun
	return entry
