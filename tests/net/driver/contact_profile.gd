extends Node
## The force on the hand of one scripted hit, tick by tick, in a networked game and in a
## local one: the contact test compares them (contact is never networked, so latency must
## not change it). The seat under test is a device paddle held still at its avatar's home;
## the first serve goes to it. The profile is the servo's telemetry (every 1 ms tick) of
## the paddle's contact force, from the first tick over [constant THRESHOLD_N] until it has
## stayed below for [constant GAP_S]. A test tool (net_peer.gd's
## [code]--pong-net-script=hit[/code] and [code]--pong-net=local[/code]).

## The local game is over (its profile is complete).
signal done

const THRESHOLD_N: float = 0.02
const GAP_S: float = 0.02
## Seconds the local game runs (the serve's flight is 1.1 s).
const LOCAL_SECONDS: float = 3.0
## The seat that receives the first serve.
const SEAT: int = 1

## [[t_s, |F| N], ...] of the first contact, t from its first tick.
var samples: Array[PackedFloat32Array] = []

var _match: PongMatch = null
var _time_column: int = 0
var _force_column: int = -1
var _stride: int = 0
var _start: float = -1.0
var _last_above: float = -1.0
var _closed: bool = false
var _screen: PongScreen = null


## [member PongNet.local_controller_factory]: a still device paddle for [param seat].
func make_still_paddle(seat: int, match_node: PongMatch) -> PongController:
	var still: PongController = PongController.new()
	still.player = seat
	still.kinematic = false
	var ai: PongAi = PongAi.new(seat, match_node.court, match_node.reach)
	still.intent.avatar = ai.home()
	still.intent.normal = (PongCourt.forward(seat) + Vector3.UP * 0.4).normalized()
	match_node.local_player = seat
	PongServo.shared().set_hand_target_3d(Vector3.ZERO)
	return still


## Where to aim a serve so that it meets the centre of a paddle held at [param home]: the
## referee's aim ignores the air's deceleration, which the servo applies, so the aim is
## moved until the ball crosses the paddle's plane at its centre (fixed-point steps of the
## servo's out-of-contact law: gravity and a constant loss of speed, 1 ms steps).
static func aim_for(court: PongCourt, home: Vector3) -> Vector3:
	var aim: Vector3 = home
	var decel: float = court.settings.air_linear_decel_m_per_s2
	for iteration: int in 6:
		var p: Vector3 = Vector3(0.0, PongReferee.SERVE_HEIGHT_M, 0.0)
		var v: Vector3 = PongReferee.launch_velocity(
			p, aim, court.gravity, PongReferee.SERVE_FLIGHT_S
		)
		var dt: float = PongServo.TICK_S
		for tick: int in 4000:
			v.y -= court.gravity * dt
			v = v.normalized() * maxf(v.length() - decel * dt, 0.0)
			var next: Vector3 = p + v * dt
			if signf(next.z - home.z) != signf(p.z - home.z):
				break
			p = next
		aim += Vector3(home.x, home.y, home.z) - Vector3(p.x, p.y, home.z)
	return aim


## Records the telemetry of [param play]'s match from now on.
func follow(play: PongNetPlay) -> void:
	_watch(play.match_node)


## The same hit without a network: a stepped local match, serve to [constant SEAT].
func play_local(health: int) -> void:
	_screen = PongNet.PONG_SCENE.instantiate() as PongScreen
	_screen.stepped = true
	_screen.start_health = health
	add_child(_screen)
	var match_node: PongMatch = _screen.match_node
	match_node.self_stepping = false
	match_node.auto_serve = false
	match_node.weapons = false
	if not _screen.start_match(PongMatch.Mode.DEMO, false):
		done.emit()
		return
	match_node.controllers[SEAT] = make_still_paddle(SEAT, match_node)
	_watch(match_node)
	match_node.referee.receiver = SEAT
	match_node.run_until(func() -> bool: return false, PongReferee.FIRST_SERVE_DELAY_S)
	var aim: Vector3 = aim_for(match_node.court, match_node.avatar_of(SEAT))
	var serve: PongReferee.Serve = match_node.referee.make_serve(match_node.court, aim, false)
	PongServo.shared().set_ball(serve.position, serve.velocity)
	var end: float = match_node.now + LOCAL_SECONDS
	while match_node.now < end:
		match_node.run_until(func() -> bool: return false, PongMatch.STEP_CHUNK_S)
		_drain()
	done.emit()


func _watch(match_node: PongMatch) -> void:
	_match = match_node
	var columns: PackedStringArray = Haptics.servo.get_telemetry_columns()
	_stride = columns.size()
	_time_column = maxi(columns.find("t"), 0)
	_force_column = columns.find("normal_x")
	Haptics.servo.drain_telemetry(HapticServoConstants.TELEMETRY_QUEUE_CAPACITY)


func _process(_delta: float) -> void:
	if _match != null and _screen == null:
		_drain()


func _drain() -> void:
	if _force_column < 0 or _closed:
		return
	var capacity: int = HapticServoConstants.TELEMETRY_QUEUE_CAPACITY
	var data: PackedFloat32Array = Haptics.servo.drain_telemetry(capacity)
	for i: int in range(0, data.size() - _stride + 1, _stride):
		var t: float = data[i + _time_column]
		var f: float = (
			Vector3(
				data[i + _force_column], data[i + _force_column + 1], data[i + _force_column + 2]
			)
			. length()
		)
		if f > THRESHOLD_N:
			if _start < 0.0:
				_start = t
			_last_above = t
		elif _start >= 0.0 and t - _last_above > GAP_S:
			_closed = true
			return
		if _start >= 0.0:
			samples.append(PackedFloat32Array([t - _start, f]))


## {samples, peak_n, impulse_n_s, duration_s}.
func to_dict() -> Dictionary:
	var peak: float = 0.0
	var impulse: float = 0.0
	var duration: float = 0.0
	for i: int in samples.size():
		peak = maxf(peak, samples[i][1])
		if samples[i][1] > THRESHOLD_N:
			duration = samples[i][0]
		if i > 0:
			impulse += samples[i][1] * (samples[i][0] - samples[i - 1][0])
	return {
		"samples": samples,
		"peak_n": peak,
		"impulse_n_s": impulse,
		"duration_s": duration,
		"complete": _closed,
	}
