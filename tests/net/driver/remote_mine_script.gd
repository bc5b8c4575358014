extends Node
## The remote-operation mine across the network, scripted for the energy test (net_peer.gd's
## [code]--pong-net-script=remote[/code]). Seat 0, the owner, places its mines (slow and
## heavy out of the way, then the remote one at the victim's avatar) and swings its
## paddle left and right all along. Seat 1, the victim, is the device player, who steps onto
## the remote mine once it lands beside it ([SteppingVictim]): the simulated
## device's hand holds the stylus at the centre, so the stylus moves only as the forces
## push it against that hand. No serve (the ball stays at rest in the middle): the only
## force on the hand while the mine runs is the coupling's.
##
## The victim's peer measures the coupling's net work on its hand over the effect: the
## servo's own count ([code]remote_work_j[/code], force times stylus velocity every 1 ms
## tick) and, as a cross-check, the rendered effect force times the stylus's displacement
## summed over the servo's telemetry (every tick).

const OWNER: int = 0
const VICTIM: int = 1
## The owner's stylus swing, along its device x: amplitude (device metres) and frequency.
const SWING_AMPLITUDE_M: float = 0.04
const SWING_HZ: float = 1.5
## Match seconds at which the owner places its three mines.
const PLACE_AT_S: Array[float] = [0.5, 1.0, 1.5]


## The owner: places its mines at the given spots, then swings its paddle.
class SwingingOwner:
	extends PongController

	var spots: Array[Vector3] = []
	var scale: float = 1.0
	var placed: int = 0
	var started: float = -1.0

	func update(
		now: float, _dt: float, _snapshot: PongState, _opponent_avatar: Vector3
	) -> PongIntent:
		if started < 0.0:
			started = now
		var t: float = now - started
		intent.place_mine = false
		if placed < PLACE_AT_S.size() and t >= PLACE_AT_S[placed]:
			intent.place_mine = true
			placed += 1
		intent.avatar = spots[maxi(placed - 1, 0)]
		var w: float = TAU * SWING_HZ
		var turn: Basis = PongCourt.side_rotation(player)
		var swing: Vector3 = Vector3(SWING_AMPLITUDE_M * sin(w * t), 0.0, 0.0)
		var rate: Vector3 = Vector3(SWING_AMPLITUDE_M * w * cos(w * t), 0.0, 0.0)
		intent.paddle_offset = turn * swing * scale
		intent.paddle_velocity = turn * rate * scale
		return intent


## The victim: stands at home until the owner's remote mine is down (a mine never lands
## on a standing player, [PongMines]: it lands beside the avatar), then steps onto it, as a
## player walks into a trap.
class SteppingVictim:
	extends PongController

	var mines: PongMines = null

	func update(
		_now: float, _dt: float, _snapshot: PongState, _opponent_avatar: Vector3
	) -> PongIntent:
		for mine: PongMines.Mine in mines.placed:
			if mine.owner == OWNER and mine.kind == "remote":
				intent.avatar = Vector3(mine.position.x, intent.avatar.y, mine.position.z)
		return intent


## Whether the victim's servo keeps the passivity rule on (off: the failing reference).
var passivity: bool = true

var _match: PongMatch = null
var _measuring: bool = false
var _done: bool = false
var _duration_s: float = 0.0
var _start_t: float = -1.0
var _work0: float = 0.0
var _work: float = 0.0
var _peak: float = 0.0
var _telemetry_work: float = 0.0
var _travel: float = 0.0
var _max_force: float = 0.0
var _ages: PackedFloat32Array = PackedFloat32Array()
var _last_position: Vector3 = Vector3.ZERO
var _last_force: Vector3 = Vector3.ZERO
var _have_last: bool = false
var _stride: int = 0
var _columns: Dictionary[String, int] = {}


## [member PongNet.local_controller_factory]: the owner's or the victim's controller.
func make_controller(seat: int, match_node: PongMatch) -> PongController:
	var court: PongCourt = match_node.court
	var victim_home: Vector3 = PongAi.new(VICTIM, court, match_node.reach).home()
	if seat == VICTIM:
		var still: SteppingVictim = SteppingVictim.new()
		still.mines = match_node.mines
		still.player = seat
		still.kinematic = false
		still.intent.avatar = victim_home
		still.intent.normal = (PongCourt.forward(seat) + Vector3.UP * 0.4).normalized()
		match_node.local_player = seat
		PongServo.shared().set_hand_target_3d(Vector3.ZERO)
		if not passivity:
			var settings: PongSettings = PongServo.shared().get_settings()
			settings.remote_passivity = false
			PongServo.shared().apply_settings(settings)
		return still
	var swinging: SwingingOwner = SwingingOwner.new()
	swinging.player = seat
	swinging.kinematic = true
	swinging.scale = court.workspace_scale
	swinging.intent.normal = (PongCourt.forward(seat) + Vector3.UP * 0.4).normalized()
	# Each mine lands at the mirror image of the owner's avatar (PongMines): stand at the
	# mirror image of where it should land.
	# The first two land as far aside as the court lets them (the mine rule clamps them):
	# the remote one lands beside the victim, PongMines.CLEAR_OF_PLAYERS_M from its feet, and
	# must stay PongMines.MIN_SPACING_M clear of them (1 m aside left it no free spot).
	var floor_spot: Vector3 = Vector3(victim_home.x, 0.0, victim_home.z)
	var aside: Vector3 = Vector3.RIGHT * court.half_width
	for target: Vector3 in [floor_spot + aside, floor_spot - aside, floor_spot]:
		var spot: Vector3 = Vector3(target.x, victim_home.y, -target.z)
		swinging.spots.append(court.clamp_avatar(seat, spot))
	return swinging


## Follows [param play]'s match: the server serves no ball; the victim's peer measures.
func follow(play: PongNetPlay) -> void:
	_match = play.match_node
	if play.authority.my_id == PongNetAuthority.SERVER_ID:
		_match.referee.serve_after(3600.0)
	if _match.local_player != VICTIM:
		return
	var columns: PackedStringArray = Haptics.servo.get_telemetry_columns()
	_stride = columns.size()
	for column: String in ["t", "position_x", "weight_x"]:
		_columns[column] = columns.find(column)
	Haptics.servo.drain_telemetry(HapticServoConstants.TELEMETRY_QUEUE_CAPACITY)
	_duration_s = _match.court.settings.mine_effect_duration_s
	_match.mine_exploded.connect(_on_mine_exploded)


func _on_mine_exploded(mine: PongMines.Mine, victim: int) -> void:
	if victim != VICTIM or mine.kind != "remote" or _measuring or _done:
		return
	_measuring = true
	_work0 = _remote_work()
	# The effect starts with the servo's next tick.
	_start_t = _match.snapshot.time_s


func _process(_delta: float) -> void:
	if _match == null or _stride == 0 or _done:
		return
	var data: PackedFloat32Array = Haptics.servo.drain_telemetry(
		HapticServoConstants.TELEMETRY_QUEUE_CAPACITY
	)
	if not _measuring:
		return
	var work: float = _remote_work() - _work0
	_work = work
	_peak = maxf(_peak, work)
	var owner_seat: PongController = _match.controllers[OWNER]
	_ages.append(owner_seat.intent.pose_age_s)
	var t_at: int = _columns["t"]
	var p_at: int = _columns["position_x"]
	var f_at: int = _columns["weight_x"]
	for i: int in range(0, data.size() - _stride + 1, _stride):
		var t: float = data[i + t_at]
		if t < _start_t:
			continue
		var position: Vector3 = Vector3(data[i + p_at], data[i + p_at + 1], data[i + p_at + 2])
		var force: Vector3 = Vector3(data[i + f_at], data[i + f_at + 1], data[i + f_at + 2])
		if _have_last:
			_telemetry_work += _last_force.dot(position - _last_position)
		_last_position = position
		_last_force = force
		_have_last = true
		_travel = maxf(_travel, position.length())
		_max_force = maxf(_max_force, force.length())
	if _match.snapshot.time_s > _start_t + _duration_s + 0.1:
		_measuring = false
		_done = true


# The servo's book of the coupling's work on the hand, J.
func _remote_work() -> float:
	return PongServo.shared().get_state().remote_work_j


## {passivity, complete, work_j, peak_work_j, telemetry_work_j, allowance_j, hand_travel_m,
## max_force_n, pose_age_p50_s, pose_age_max_s}.
func to_dict() -> Dictionary:
	var cap: float = 0.0
	var stiffness: float = 1.0
	if _match != null:
		cap = _match.court.settings.remote_max_force_n
		stiffness = _match.court.settings.remote_stiffness_n_per_m
	var ages: PackedFloat32Array = _ages.duplicate()
	ages.sort()
	return {
		"passivity": passivity,
		"started": _start_t >= 0.0,
		"complete": _done,
		"work_j": _work,
		"peak_work_j": _peak,
		"telemetry_work_j": _telemetry_work,
		"allowance_j": 0.5 * cap * cap / stiffness,
		"hand_travel_m": _travel,
		"max_force_n": _max_force,
		"pose_age_p50_s": ages[floori(ages.size() * 0.5)] if not ages.is_empty() else -1.0,
		"pose_age_max_s": ages[-1] if not ages.is_empty() else -1.0,
	}
