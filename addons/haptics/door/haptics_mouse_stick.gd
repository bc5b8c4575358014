class_name HapticsMouseStick
extends RefCounted
## The mouse stick as the player holds it, for a game to draw ([method Haptics.get_mouse_stick]):
## the left button pressed in the game (not on a control) grips it at [member origin]; the
## pointer's offset from there, up to [member radius], is the hand's deflection.

## Whether it is held (and steers the simulated hand).
var held: bool = false
## Where it was gripped, viewport pixels.
var origin: Vector2 = Vector2.ZERO
## Where the pointer is, viewport pixels.
var pointer: Vector2 = Vector2.ZERO
## The full deflection, pixels.
var radius: float = 1.0


## The deflection it gives: the pointer's offset from [member origin] over [member radius],
## at most 1 long (zero while not held).
func deflection() -> Vector2:
	if not held:
		return Vector2.ZERO
	return ((pointer - origin) / radius).limit_length(1.0)
