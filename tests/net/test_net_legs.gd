extends TestSuite
## Each direction's delay from the heartbeat (PongNetLegs): two ends exchange beats over a
## simulated path, each stamping beats with its own system clock, and split ENet's round trip
## by what the two measured. On a 50/250 ms path with clocks 5 ms apart each end finds its
## own two legs; clocks a second apart, a forged stamp or a peer not yet heard give half the
## round trip each way, never a negative or a longer leg.

const A: int = 1
const B: int = 42
const BEAT_S: float = 0.2


## Beats between a client [param client] and its server [param server] for [param seconds]:
## up [param up_s] and down [param down_s] (each plus up to [param jitter_s]), the client's
## clock [param skew_s] ahead of the server's.
func _exchange(
	client: PongNetLegs,
	server: PongNetLegs,
	up_s: float,
	down_s: float,
	jitter_s: float,
	skew_s: float,
	seconds: float = 6.0
) -> void:
	var rng: RandomNumberGenerator = RandomNumberGenerator.new()
	rng.seed = 7
	var server_clock: float = 1.8e9
	var now: float = 0.0
	while now < seconds:
		var up: float = up_s + rng.randf() * jitter_s
		var client_stamp: float = server_clock + now + skew_s
		server.heard(B, server_clock + now + up, client_stamp, client.inbound_ms(A))
		var down: float = down_s + rng.randf() * jitter_s
		var server_stamp: float = server_clock + now
		client.heard(A, server_clock + now + down + skew_s, server_stamp, server.inbound_ms(B))
		now += BEAT_S


func test_a_50_250_ms_path_is_split_into_its_two_legs() -> void:
	var client: PongNetLegs = PongNetLegs.new()
	var server: PongNetLegs = PongNetLegs.new()
	_exchange(client, server, 0.05, 0.25, 0.03, 0.005)
	# ENet's round trip is a smoothed mean: the jitter's mean on top of the fastest legs.
	var round_trip: float = 0.33
	var at_client: Vector2 = client.split(A, round_trip)
	var at_server: Vector2 = server.split(B, round_trip)
	assert_almost_eq(at_client, Vector2(0.055, 0.275), 0.02, "client: up, down")
	assert_almost_eq(at_server, Vector2(0.275, 0.055), 0.02, "server: to the client, from it")
	assert_almost_eq(at_client.x + at_client.y, round_trip, 1e-6, "the legs make the trip")


func test_clocks_a_second_apart_fall_back_to_half_the_round_trip() -> void:
	for skew: float in [1.0, -1.0]:
		var client: PongNetLegs = PongNetLegs.new()
		var server: PongNetLegs = PongNetLegs.new()
		_exchange(client, server, 0.05, 0.25, 0.0, skew)
		assert_eq(client.split(A, 0.3), Vector2(0.15, 0.15), "skew %s s" % skew)
		assert_eq(server.split(B, 0.3), Vector2(0.15, 0.15), "skew %s s" % skew)


func test_an_unheard_peer_and_a_peer_that_heard_nothing_get_half_each_way() -> void:
	var legs: PongNetLegs = PongNetLegs.new()
	assert_eq(legs.split(A, 0.2), Vector2(0.1, 0.1), "nothing heard")
	legs.heard(A, 100.05, 100.0, NAN)
	assert_almost_eq(legs.inbound_ms(A), 50.0, 1e-6, "its beat took 50 ms")
	assert_eq(legs.split(A, 0.2), Vector2(0.1, 0.1), "it has not told us ours yet")
	legs.forget(A)
	assert_true(is_nan(legs.inbound_ms(A)), "forgotten")


func test_a_forged_or_broken_stamp_never_makes_a_leg_negative_or_longer_than_the_trip() -> void:
	var legs: PongNetLegs = PongNetLegs.new()
	for stamp: float in [100.0, 99.9e6, INF, NAN, -1e30]:
		legs.heard(A, 100.05, stamp, 40.0)
		var split: Vector2 = legs.split(A, 0.1)
		assert_true(split.x >= 0.0 and split.y >= 0.0, "stamp %s: %s" % [stamp, split])
		assert_almost_eq(split.x + split.y, 0.1, 1e-6, "stamp %s: the trip" % stamp)
	# A stamp from the future (a forged one) is the fastest beat for the window it stays in,
	# and makes the split fall back rather than bend.
	legs.heard(A, 100.05, 200.0, 40.0)
	assert_eq(legs.split(A, 0.1), Vector2(0.05, 0.05), "a stamp 100 s ahead")
	# It leaves the window after PongNetLegs.WINDOW honest beats.
	for _beat: int in PongNetLegs.WINDOW:
		legs.heard(A, 100.05, 100.0, 40.0)
	assert_almost_eq(legs.split(A, 0.09), Vector2(0.04, 0.05), 1e-6, "honest again")
