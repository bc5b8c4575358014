extends RefCounted
## A scripted network path for the ball stream, without sockets: each datagram sent at a
## time arrives [member delay_s] ± [member jitter_s] (uniform, independent per datagram, so
## it reorders whenever the jitter exceeds the send period) later, unless a loss burst
## (started with [member burst_start_chance] per datagram, [member burst_min]..
## [member burst_max] datagrams long) swallows it; a delivered one arrives twice with
## [member duplicate_chance] (the copy with its own delay). Seeded: the same stream every
## run. The issue's path (issue 24): 200 ± 60 ms, 10 % loss in bursts of 3-10, 1 % copies.

var delay_s: float = 0.2
var jitter_s: float = 0.06
var burst_min: int = 3
var burst_max: int = 10
## 10 % of datagrams lost: bursts of 6.5 on average, each started after a datagram that got
## through with this chance (0.1 = 6.5 c / (1 + 6.5 c - c)).
var burst_start_chance: float = 0.1 / (6.5 - 0.1 * 5.5)
var duplicate_chance: float = 0.01
## Datagrams sent, lost, copied.
var sent: int = 0
var lost: int = 0
var copies: int = 0

var _rng: RandomNumberGenerator = RandomNumberGenerator.new()
var _burst_left: int = 0


func _init(seed_value: int = 24) -> void:
	_rng.seed = seed_value


## The arrival times of one datagram sent at [param sent_s]: none, one, or two.
func arrivals(sent_s: float) -> PackedFloat64Array:
	sent += 1
	var out: PackedFloat64Array = PackedFloat64Array()
	if _burst_left == 0 and _rng.randf() < burst_start_chance:
		_burst_left = _rng.randi_range(burst_min, burst_max)
	if _burst_left > 0:
		_burst_left -= 1
		lost += 1
		return out
	out.append(sent_s + _one_delay())
	if _rng.randf() < duplicate_chance:
		copies += 1
		out.append(sent_s + _one_delay())
	return out


func _one_delay() -> float:
	return delay_s + _rng.randf_range(-jitter_s, jitter_s)


## Takes every paddle out of play in the servo: only the court and the commands move the ball.
static func no_paddles() -> void:
	var input: PongInput = PongInput.new()
	for player: PongPlayerInput in input.players:
		player.active = false
		player.kinematic = true
	PongServo.shared().set_input(input)
