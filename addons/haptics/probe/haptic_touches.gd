extends RefCounted
## Which shapes a probe's body touches, frame to frame: a touch that begins is an impact, and
## a shape lost for less than the release time and touched again is the same touch (a rigid
## body riding a moving platform loses and regains it every few frames). A new touch of a
## collider's surface that the body touched on the frame before, at about the same normal, is
## that surface going on (the next tile or GridMap cell of one floor): no impact either.

## Normals closer than this (cosine, about 16°) are one surface going on: cells of one floor
## meet with normals a few degrees apart at their seams.
const SAME_SURFACE_COS := 0.96

# Each touched shape's key (as the probe's contacts name it) with the physics frame it was
# last touched on.
var _touching: Dictionary[String, int] = {}
# The normals touched, by collider id: on this frame, and on the one before.
var _surfaces: Dictionary[int, PackedVector3Array] = {}
var _surfaces_before: Dictionary[int, PackedVector3Array] = {}


## Notes that the shape [param key] of collider [param id] is touched on physics frame
## [param now] at [param normal] (a 2D normal as its Vector3); true when the touch is new and
## not a surface of the frame before going on.
func touch(key: String, now: int, id: int, normal: Vector3) -> bool:
	var began: bool = not _touching.has(key)
	_touching[key] = now
	var seen: PackedVector3Array = _surfaces.get(id, PackedVector3Array())
	seen.append(normal)
	_surfaces[id] = seen
	return began and not _goes_on(id, normal)


## Ends the frame [param now]: forgets the shapes not touched for longer than
## [param release_s] (touching them again is a new touch).
func release(now: int, release_s: float) -> void:
	var hold_frames: int = ceili(release_s * Engine.physics_ticks_per_second)
	for key: String in _touching.keys():
		if now - _touching[key] > hold_frames:
			_touching.erase(key)
	_surfaces_before = _surfaces
	_surfaces = {}


func _goes_on(id: int, normal: Vector3) -> bool:
	for before: Vector3 in _surfaces_before.get(id, PackedVector3Array()):
		if before.dot(normal) > SAME_SURFACE_COS:
			return true
	return false
