extends RefCounted
## Runs a test's own door ([code]HapticsTestKit.manual()[/code]) in step with the game: after
## each physics frame, 1 ms servo ticks until device time has caught up with game time,
## recording what the device received on every tick (its [HapticForces], newtons, game axes:
## [code]total[/code], [code]impact[/code], and the movement renderer's [code]weight[/code],
## [code]drag[/code], [code]inertia[/code], [code]normal[/code]).

## One servo tick, seconds.
const TICK_S := 0.001
## The forces recorded per tick: [code]total[/code], [code]impact[/code], then movement
## components by their names in [code]HapticMovementFacts.MOVEMENT_FORCE_NAMES[/code].
const KEYS: PackedStringArray = ["total", "impact", "weight", "drag", "inertia", "normal"]

## Each tick's record: [code]t[/code] (device seconds) and one Vector2 per [constant KEYS].
var samples: Array[Dictionary] = []

var _door: HapticsTestKit.Door = null
var _device_time: float = 0.0
var _game_time: float = 0.0


func _init(door: HapticsTestKit.Door) -> void:
	_door = door


## Runs the servo through [param dt] seconds of game time (one physics frame).
func run(dt: float) -> void:
	_game_time += dt
	while _device_time + TICK_S * 0.5 < _game_time:
		_door.servo.step(TICK_S)
		_device_time += TICK_S
		var forces: HapticForces = _door.get_forces()
		var sample: Dictionary = {"t": _device_time, "total": forces.total, "impact": forces.impact}
		for key: String in KEYS:
			var part: int = HapticMovementFacts.MOVEMENT_FORCE_NAMES.find(key)
			if part >= 0:
				sample[key] = forces.parts[part]
		samples.append(sample)


## The largest component of force [param key] along [param direction] from sample
## [param from] on, newtons (0 when it never points that way).
func peak(key: String, direction: Vector2, from: int = 0) -> float:
	var best: float = 0.0
	for i: int in range(from, samples.size()):
		var force: Vector2 = samples[i][key]
		best = maxf(best, force.dot(direction))
	return best


## The largest magnitude of force [param key] across [param direction] (its sideways part)
## from sample [param from] on, newtons.
func peak_across(key: String, direction: Vector2, from: int = 0) -> float:
	var best: float = 0.0
	for i: int in range(from, samples.size()):
		var force: Vector2 = samples[i][key]
		best = maxf(best, absf(force.cross(direction)))
	return best


## Seconds from the first to the last sample (from [param from] on) in which force
## [param key] reaches [param threshold] newtons; 0 when it never does.
func duration(key: String, threshold: float, from: int = 0) -> float:
	var first: float = -1.0
	var final: float = -1.0
	for i: int in range(from, samples.size()):
		var force: Vector2 = samples[i][key]
		if force.length() >= threshold:
			var t: float = samples[i]["t"]
			if first < 0.0:
				first = t
			final = t
	return 0.0 if first < 0.0 else final - first + TICK_S


## Force [param key] on the last tick.
func last(key: String) -> Vector2:
	if samples.is_empty():
		return Vector2.ZERO
	var force: Vector2 = samples[-1][key]
	return force
