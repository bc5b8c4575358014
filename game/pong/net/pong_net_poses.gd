class_name PongNetPoses
extends RefCounted
## The paddles' poses in a networked match: on each new servo state a peer sends the pose
## of every seat it drives ([PongNetPoseMessage]: avatar, paddle offset and velocity, normal,
## modes, servo time, its leg to the server) unreliable and ordered; a pose received, once
## checked against the match (the seat is the sender's and in this court), moves that seat's
## [PongNetRemotePlayer] here, carried on by its age.

## A pose of [param seat] moved its remote player here.
signal pose_taken(seat: int)
## [param sender]'s [param pose], checked, was taken (the server's ball check reads the
## master's).
signal pose_received(sender: int, pose: PongNetPoseMessage)

## Paddle speeds sent are capped here (a teleported avatar is not a swing), m/s.
const MAX_SENT_PADDLE_SPEED_M_PER_S: float = 20.0

var _router: PongNetRouter = null
var _match: PongMatch = null
var _authority: PongNetAuthority = null
var _reject: Callable = Callable()
var _age_of: Callable = Callable()
# Per seat its paddle centre when last sent, and under -1 - seat the match time then.
var _last_centers: Dictionary[int, Vector3] = {}


## Sends and takes through [param router] and moves the players of [param p_match];
## [param p_reject] and [param p_age_of] as [PongNetWeapons] takes them.
func _init(
	router: PongNetRouter,
	p_match: PongMatch,
	authority: PongNetAuthority,
	p_reject: Callable,
	p_age_of: Callable
) -> void:
	_router = router
	_match = p_match
	_authority = authority
	_reject = p_reject
	_age_of = p_age_of
	_router.handle(PongNetPoseMessage.SCHEMA_ID, on_pose)


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
		var pose: PongNetPoseMessage = PongNetPoseMessage.new()
		pose.seat = seat
		pose.avatar = avatar
		pose.offset = offset
		pose.velocity = velocity
		pose.normal = normal
		pose.spin = _match.controllers[seat].intent.spin
		pose.gun = _match.controllers[seat].intent.gun
		pose.time_s = snapshot.time_s
		pose.leg_ms = leg_ms
		_router.send_all(pose)


## A pose from [param sender], its fields checked ([PongNetRouter]).
func on_pose(sender: int, pose: PongNetPoseMessage) -> void:
	var reason: String = PongNetProtocol.check_seat(pose.seat, _authority.owners.size())
	if reason.is_empty():
		var limit: Vector3 = PongNetProtocol.position_limit(_match.court)
		reason = PongNetProtocol.check_box(pose.avatar, limit, "avatar")
	# The server may drive any seat: it takes over the seats of players who left, and its
	# poses can overtake the reliable message that says so.
	var seat_owner: int = _authority.owner_of(pose.seat)
	if reason.is_empty() and seat_owner != sender and sender != PongNetAuthority.SERVER_ID:
		reason = "seat %d is not theirs" % pose.seat
	if not reason.is_empty():
		_reject.call(sender, PongNetPoseMessage.LABEL, reason)
		return
	_router.forward(sender, pose)
	var controller: PongController = _match.controllers[pose.seat]
	if not controller is PongNetRemotePlayer:
		return
	var age: float = _age_of.call(sender, pose.time_s, pose.leg_ms)
	(controller as PongNetRemotePlayer).set_pose(_match.now, clampf(age, 0.0, 0.5), pose)
	pose_taken.emit(pose.seat)
	pose_received.emit(sender, pose)
