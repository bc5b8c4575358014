class_name PongNetPoses
extends RefCounted
## The paddles' poses in a networked match: on each new servo state a peer sends the pose
## of every seat it drives (avatar, paddle offset and velocity, normal, modes, servo time,
## its leg to the server) unreliable and ordered; a pose received, once checked, moves that
## seat's [PongNetRemotePlayer] here, carried on by its age.

## Paddle speeds sent are capped here (a teleported avatar is not a swing), m/s.
const MAX_SENT_PADDLE_SPEED_M_PER_S: float = 20.0

var _wire: PongNetWire = null
var _match: PongMatch = null
var _authority: PongNetAuthority = null
var _report: PongNetReport = null
var _reject: Callable = Callable()
var _age_of: Callable = Callable()
# Per seat its paddle centre when last sent, and under -1 - seat the match time then.
var _last_centers: Dictionary[int, Vector3] = {}


## Sends through [param wire] and moves the players of [param p_match]; [param p_reject]
## and [param p_age_of] as [PongNetWeapons] takes them.
func _init(
	wire: PongNetWire,
	p_match: PongMatch,
	authority: PongNetAuthority,
	report: PongNetReport,
	p_reject: Callable,
	p_age_of: Callable
) -> void:
	_wire = wire
	_match = p_match
	_authority = authority
	_report = report
	_reject = p_reject
	_age_of = p_age_of


## Sends the poses of [param seats] from [param snapshot], with our leg [param leg_ms].
func send(snapshot: PongState, seats: PackedInt32Array, leg_ms: int) -> void:
	for seat: int in seats:
		var avatar: Vector3 = _match.avatar_of(seat)
		var offset: Vector3 = snapshot.paddle_centers[seat] - avatar
		var velocity: Vector3 = Vector3.ZERO
		var dt: float = _match.now - _last_centers.get(-1 - seat, Vector3.ZERO).x
		if _last_centers.has(seat) and dt > 0.0:
			velocity = (snapshot.paddle_centers[seat] - _last_centers[seat]) / dt
		_last_centers[seat] = snapshot.paddle_centers[seat]
		_last_centers[-1 - seat] = Vector3(_match.now, 0.0, 0.0)
		velocity = velocity.limit_length(MAX_SENT_PADDLE_SPEED_M_PER_S)
		var normal: Vector3 = snapshot.paddle_normals[seat].normalized()
		if normal.is_zero_approx():
			# Before the servo's first state (whose normals start at zero): the seat's own
			# facing, which is what the servo makes of a zero normal too.
			normal = PongCourt.forward(seat)
		var flags: int = PongNetRemotePlayer.flags_of(_match.controllers[seat].intent)
		_wire.send_all(
			&"_pose", [seat, avatar, offset, velocity, normal, flags, snapshot.time_s, leg_ms]
		)


## A pose from [param sender] (every argument unchecked).
func on_pose(
	sender: int,
	seat: Variant,
	avatar: Variant,
	offset: Variant,
	velocity: Variant,
	normal: Variant,
	flags: Variant,
	time_s: Variant,
	leg_ms: Variant
) -> void:
	var reason: String = PongNetProtocol.check_pose(
		seat, _authority.owners.size(), avatar, offset, velocity, normal, _match.court, 2.0
	)
	if reason.is_empty():
		reason = PongNetProtocol.check_int(flags, 0, 3, "flags")
	if reason.is_empty():
		reason = PongNetProtocol.check_float(time_s, 0.0, 1e7, "time")
	if reason.is_empty():
		reason = PongNetProtocol.check_int(leg_ms, 0, 10000, "leg")
	if not reason.is_empty():
		_reject.call(sender, "pose", reason)
		return
	var pose_seat: int = seat
	var sent_at: float = time_s
	var pose: Array[Vector3] = [avatar, offset, velocity, normal]
	var pose_flags: int = flags
	# The server may drive any seat: it takes over the seats of players who left, and its
	# poses can overtake the reliable message that says so.
	var seat_owner: int = _authority.owner_of(pose_seat)
	if seat_owner != sender and sender != PongNetAuthority.SERVER_ID:
		_reject.call(sender, "pose", "seat %d is not theirs" % pose_seat)
		return
	var controller: PongController = _match.controllers[pose_seat]
	if not controller is PongNetRemotePlayer:
		return
	var leg: int = leg_ms
	var age: float = _age_of.call(sender, sent_at, leg)
	(controller as PongNetRemotePlayer).set_pose(
		_match.now, minf(age, 0.5), pose[0], pose[1], pose[2], pose[3], pose_flags
	)
	_report.poses += 1
