extends RefCounted
## Which shapes a probe's body touches, frame to frame: a touch that begins is an impact, and
## a shape lost for less than the release time and touched again is the same touch (a rigid
## body riding a moving platform loses and regains it every few frames).

# Each touched shape's key (as the probe's contacts name it) with the physics frame it was
# last touched on.
var _touching: Dictionary[String, int] = {}


## Notes that the shape [param key] is touched on physics frame [param now]; true when the
## touch is new.
func touch(key: String, now: int) -> bool:
	var began: bool = not _touching.has(key)
	_touching[key] = now
	return began


## Forgets the shapes not touched for longer than [param release_s]: touching them again is
## a new touch.
func release(now: int, release_s: float) -> void:
	var hold_frames: int = ceili(release_s * Engine.physics_ticks_per_second)
	for key: String in _touching.keys():
		if now - _touching[key] > hold_frames:
			_touching.erase(key)
