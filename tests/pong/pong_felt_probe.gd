extends RefCounted
## Drives a stepped [PongMatch] the way its own chunks do (the servo's ticks, then one update
## of the match) and keeps what the device received on every tick: the servo's hand force
## [code]total[/code] (device space, newtons) with the servo's whole state. What the
## game-action tests read their forces from, tick by tick.

## One state per servo tick since the probe was made, oldest first.
var states: Array[PongState] = []

var _match: PongMatch = null
var _ticks_per_chunk: int = 0


func _init(match_node: PongMatch) -> void:
	_match = match_node
	_ticks_per_chunk = roundi(PongMatch.STEP_CHUNK_S / PongServo.TICK_S)


## Runs the match for up to [param max_s] simulated seconds; after each update
## [param after_chunk] (when valid) is called, and the run stops when it returns true.
## Returns whether it did.
func run(max_s: float, after_chunk: Callable = Callable()) -> bool:
	for chunk: int in ceili(max_s / PongMatch.STEP_CHUNK_S - 1e-6):
		for tick: int in _ticks_per_chunk:
			if not PongServo.shared().step_ticks(1):
				return false
			states.append(PongServo.shared().get_state())
		_match.advance(PongMatch.STEP_CHUNK_S)
		if after_chunk.is_valid() and after_chunk.call():
			return true
	return false


## The index the next tick's state will have.
func mark() -> int:
	return states.size()


## The force on tick [param index] (device space, N).
func force(index: int) -> Vector3:
	return states[index].hand_force.total


## The index of the largest |force| in [[param from], [param to]) (to -1: the end).
func peak_index(from: int, to: int = -1) -> int:
	var best: int = from
	for i: int in range(from, _end(to)):
		if force(i).length() > force(best).length():
			best = i
	return best


## The largest |force| in [[param from], [param to]), newtons.
func peak(from: int, to: int = -1) -> float:
	return force(peak_index(from, to)).length() if from < _end(to) else 0.0


## Seconds from the first to the last tick in [[param from], [param to]) whose |force| is
## at least [param threshold_n] (0 when none is).
func span_s(from: int, threshold_n: float, to: int = -1) -> float:
	var first: int = -1
	var last: int = -1
	for i: int in range(from, _end(to)):
		if force(i).length() >= threshold_n:
			if first < 0:
				first = i
			last = i
	return 0.0 if first < 0 else (last - first + 1) * PongServo.TICK_S


## The mean force over [[param from], [param to]).
func mean(from: int, to: int) -> Vector3:
	var sum: Vector3 = Vector3.ZERO
	for i: int in range(from, _end(to)):
		sum += force(i)
	return sum / maxi(_end(to) - from, 1)


## The tick whose servo time is closest to [param time_s] (an event's time).
func index_at(time_s: float) -> int:
	var best: int = 0
	for i: int in states.size():
		if absf(states[i].time_s - time_s) < absf(states[best].time_s - time_s):
			best = i
	return best


func _end(to: int) -> int:
	return states.size() if to < 0 else mini(to, states.size())
