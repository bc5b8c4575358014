class_name Room3DPilot
extends RefCounted
## Steers the [Room3D]'s explorer in place of the person, as [GamePilot] does for level 1:
## the room asks it every physics tick. The game has none of its own; test drivers extend it.


## Sets [member Explorer.input_vector] of [param _room]'s explorer for one physics tick of
## [param _delta] seconds; false stops it (the explorer lets go).
func steer(_room: Room3D, _delta: float) -> bool:
	return true
