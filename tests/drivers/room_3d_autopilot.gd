class_name Room3DAutopilot
extends Room3DPilot
## Walks the [Room3D]'s explorer along [constant Room3D.PATH] to the goal, moving on within
## [constant REACHED_M] of each waypoint. The simulated hand follows the input it sets, so
## the device agrees with what the pilot does.

## How near a waypoint counts as reached, in metres.
const REACHED_M := 0.4

## The waypoint walked to now.
var next: int = 0


func steer(room: Room3D, _delta: float) -> bool:
	if next >= Room3D.PATH.size():
		return false
	var here: Vector3 = room.explorer.position
	var target: Vector3 = Room3D.PATH[next]
	var to_target: Vector3 = Vector3(target.x - here.x, 0.0, target.z - here.z)
	if to_target.length() < REACHED_M:
		next += 1
		return steer(room, _delta)
	var push: Vector3 = to_target.normalized()
	room.explorer.input_vector = push
	# The hand in view axes (the camera looks along -z: the same axes).
	Haptics.device.set_hand_target_3d(push * 0.8 * Haptics.device.get_workspace_radius())
	return true
