class_name PongNetHalfOpen
extends RefCounted
## The server's connections that have connected at ENet's level but not passed the version
## check, by address: each address may hold [member per_address] of them; a newer one pushes
## the oldest out, so a stream of connections that never authenticate holds at most that
## many, and a real player's fresh connection from the same address still gets its turn.
## (The version check's own deadline, [constant PongNetProtocol.AUTH_TIMEOUT_S], drops the
## rest.)

## Half-open connections an address may hold.
var per_address: int = PongNetProtocol.HALF_OPEN_PER_ADDRESS

# Peer id -> [address, since (s)], in arrival order (a Dictionary keeps it).
var _open: Dictionary[int, Array] = {}


func _init(p_per_address: int = PongNetProtocol.HALF_OPEN_PER_ADDRESS) -> void:
	per_address = maxi(p_per_address, 1)


## [param peer] from [param address] began the version check at [param now_s]. Returns the
## peers to drop now (the oldest of that address beyond the limit), no longer tracked.
func add(peer: int, address: String, now_s: float) -> Array[int]:
	_open[peer] = [address, now_s]
	var same: Array[int] = []
	for other: int in _open:
		if _open[other][0] == address:
			same.append(other)
	var dropped: Array[int] = []
	while same.size() > per_address:
		var oldest: int = same.pop_front()
		_open.erase(oldest)
		dropped.append(oldest)
	return dropped


## [param peer] passed the check, failed it or left.
func remove(peer: int) -> void:
	_open.erase(peer)


## How many half-open connections [param address] holds.
func count(address: String) -> int:
	var n: int = 0
	for entry: Array in _open.values():
		n += 1 if entry[0] == address else 0
	return n


func clear() -> void:
	_open.clear()
