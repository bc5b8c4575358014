class_name HapticFrame
extends RefCounted
## One physics tick's haptic frame, as a [HapticProbe] gathers it: the body's contacts, the
## bodies resting on it, the water it is in and its velocity. [method to_dictionary] writes
## the layout [code]HapticsServer.submit_frame[/code] reads; a new frame (nothing touched,
## at rest, out of water) is the heartbeat that keeps the servo's watchdog fed.

## At most [code]MAX_CONTACTS[/code] (the server's constant).
var contacts: Array[HapticContact] = []
## At most [code]MAX_RESTING_OBJECTS[/code] (the server's constant).
var resting: Array[HapticLoad] = []
## Whether the body is in water; the drag and inertia below count only then.
var in_water: bool = false
## Water drag coefficient, N·s/m.
var water_drag_n_s_per_m: float = 0.0
## Water inertia force, N.
var water_inertia_n: float = 0.0
## The body's velocity, m/s, game axes.
var velocity_m_per_s: Vector2 = Vector2.ZERO
## The game's own frame counter (telemetry, debugging).
var sequence: int = 0
## Game time of the frame, seconds.
var time_s: float = 0.0


## The dictionary [code]HapticsServer.submit_frame[/code] takes.
func to_dictionary() -> Dictionary:
	var water: Dictionary = {"inside": in_water}
	if in_water:
		water["drag_n_s_per_m"] = water_drag_n_s_per_m
		water["inertia_n"] = water_inertia_n
	return {
		"contacts": contacts.map(func(c: HapticContact) -> Dictionary: return c.to_dictionary()),
		"resting": resting.map(func(r: HapticLoad) -> Dictionary: return r.to_dictionary()),
		"water": water,
		"velocity_m_per_s": velocity_m_per_s,
		"sequence": sequence,
		"time_s": time_s,
	}
