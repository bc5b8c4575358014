extends TestSuite
## The server's watch on its master's stream, without sockets: a client master that is heard
## but streams nothing the server can play for 2 s of the server's frames is counted once
## and the server takes the ball; a fed stream, a silent master (an outage: the heartbeat's
## matter), a stalling one, the server's own ball and the server's own stall never are.

const HOST: int = 1
const CLIENT: int = 42
const FRAME_S: float = 1.0 / 60.0

var _authority: PongNetAuthority = null
var _heartbeat: PongNetHeartbeat = null
var _watch: PongNetStreamWatch = null
var _rejected: Array[Array] = []
var _taken_by: Array[int] = []


func before_each() -> void:
	_authority = PongNetAuthority.new(HOST, PackedInt64Array([HOST, CLIENT]))
	_heartbeat = PongNetHeartbeat.new()
	_heartbeat.watch(CLIENT, 0.0)
	_rejected = []
	_taken_by = []
	_watch = PongNetStreamWatch.new(
		_authority,
		_heartbeat,
		func(peer: int, what: String, why: String) -> void: _rejected.append([peer, what, why]),
		func(master: int) -> void: _taken_by.append(master)
	)


func _master(peer: int) -> void:
	var territory: int = 0 if peer == HOST else 1
	var next: Dictionary = _authority.next_transfer(PongNetFacts.TransferKind.SERVE, territory)
	assert_eq(_authority.apply_transfer(HOST, next), "")
	assert_eq(_authority.master_peer, peer)


# Frames from [param from_s] for [param seconds], the client heard each frame when
# [param heard], its stream fed every [param feed_every] frames (0: never); the first
# second (from [param from_s]) at which the watch said dry, or INF.
func _run(from_s: float, seconds: float, heard: bool = true, feed_every: int = 0) -> float:
	var frames: int = roundi(seconds / FRAME_S)
	for frame: int in frames:
		var now: float = from_s + frame * FRAME_S
		if heard:
			_heartbeat.heard(CLIENT, now)
		if feed_every > 0 and frame % feed_every == 0:
			_watch.fed()
		if _watch.update(FRAME_S, now):
			return now - from_s
	return INF


func test_a_heard_master_streaming_nothing_is_counted_once_and_the_server_takes_the_ball() -> void:
	_master(CLIENT)
	var dry_at: float = _run(0.0, 10.0)
	assert_almost_eq(dry_at, PongNetStreamWatch.DRY_S, 2.0 * FRAME_S, "after 2 s of frames")
	assert_eq(_rejected.size(), 1, "counted once")
	if _rejected.size() == 1:
		assert_eq(_rejected[0][0], CLIENT, "against the master")
		assert_true(str(_rejected[0][2]).contains("no state the server could play"))
	assert_eq(_taken_by, [HOST], "the server takes the ball, as its master")
	# The takeover's transfer starts a new epoch; a client master of it is watched afresh.
	_master(CLIENT)
	assert_almost_eq(_run(10.0, 10.0), PongNetStreamWatch.DRY_S, 2.0 * FRAME_S, "and again")
	assert_eq(_rejected.size(), 2)


func test_a_fed_stream_a_silent_master_and_a_stalling_one_are_never_dry() -> void:
	_master(CLIENT)
	assert_eq(_run(0.0, 20.0, true, 90), INF, "a state taken every 1.5 s")
	# An outage: nothing heard from the client (the heartbeat stands the computer in).
	assert_eq(_run(20.0, 20.0, false), INF, "silent")
	# 1.9 s dry, then the client says it stalls (it loads): its silence after is no dry stream.
	_master(CLIENT)
	assert_eq(_run(40.0, 1.9), INF)
	_heartbeat.stalls(CLIENT, 41.9)
	for frame: int in 30:
		assert_false(_watch.update(FRAME_S, 41.9 + frame * FRAME_S), "stalling")
	assert_eq(_rejected, [], "nothing counted")


func test_the_servers_own_ball_and_its_own_stall_are_no_dry_stream() -> void:
	_master(HOST)
	assert_eq(_run(0.0, 10.0), INF, "the server masters the ball")
	_master(CLIENT)
	_heartbeat.heard(CLIENT, 10.0)
	# The server's own stall of 5 s: one frame counts a tenth of a second at most.
	assert_false(_watch.update(5.0, 10.0), "one long frame")
	assert_almost_eq(
		_run(10.0, 10.0), PongNetStreamWatch.DRY_S - PongNetStreamWatch.FRAME_MAX_S, 2.0 * FRAME_S
	)
