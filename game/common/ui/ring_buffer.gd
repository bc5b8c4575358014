class_name RingBuffer
extends RefCounted
## A fixed-capacity ring of floats: pushing never allocates once constructed; when full,
## the oldest sample is overwritten.

## How many samples the ring holds.
var capacity: int:
	get:
		return _data.size()

var _data: PackedFloat32Array = PackedFloat32Array()
var _head: int = 0
var _count: int = 0


func _init(p_capacity: int = 300) -> void:
	_data.resize(maxi(p_capacity, 1))
	_data.fill(0.0)


## Appends [param value], dropping the oldest sample when full.
func push(value: float) -> void:
	_data[_head] = value
	_head = (_head + 1) % _data.size()
	_count = mini(_count + 1, _data.size())


## Number of samples held (at most [member capacity]).
func size() -> int:
	return _count


## Whether no sample was pushed since construction or [method clear].
func is_empty() -> bool:
	return _count == 0


## Sample [param index], 0 being the oldest held and [code]size() - 1[/code] the newest.
func get_value(index: int) -> float:
	if index < 0 or index >= _count:
		return 0.0
	var start: int = (_head - _count + _data.size()) % _data.size()
	return _data[(start + index) % _data.size()]


## The newest sample (0 when empty).
func last() -> float:
	return get_value(_count - 1)


## Largest sample held (0 when empty).
func max_value() -> float:
	var best: float = 0.0
	for i: int in _count:
		best = maxf(best, get_value(i))
	return best


## Forgets every sample (keeps the storage).
func clear() -> void:
	_head = 0
	_count = 0


## The samples oldest first, as a new array (allocates: for tests and tools).
func to_array() -> PackedFloat32Array:
	var out: PackedFloat32Array = PackedFloat32Array()
	out.resize(_count)
	for i: int in _count:
		out[i] = get_value(i)
	return out
