class_name PongAi
extends PongController
## The computer player: it watches the ball (with a reaction delay), predicts its path
## with [PongPredictor], picks the first point where it can meet the ball in the air in its
## own half (before the ball bounces there when it can), walks its avatar there, and swings
## its kinematic paddle through that point.
##
## The swing follows the mirror law of a kinematic paddle: the ball leaves a paddle moving
## at u along its normal n with its normal velocity reflected in the paddle's frame and
## scaled by the paddle's restitution e, [code]v_out = v_in - (1 + e) ((v_in - u n) . n) n[/code].
## For a wanted [code]v_out[/code] (a lob that lands in the opponent's half, or in beginner
## mode a shot at the target on the opponent's back wall) that gives
## [code]n = unit(v_out - v_in)[/code] and [code]u = v_in . n + |v_out - v_in| / (1 + e)[/code].
##
## It plays reasonably, not perfectly: the knobs below (reaction delay, contact-point and
## aim errors, avatar speed) make it miss now and then. Randomness comes from its own
## seeded generator, so a match replays the same. [PongAiLevel] sets the knobs for a
## difficulty level; the defaults below are its NORMAL.


## A planned contact with the ball.
class Contact:
	extends RefCounted
	## When (absolute time once planned; seconds from the observation in plan_contact).
	var time: float = 0.0
	## Where the paddle meets the ball, world.
	var point: Vector3 = Vector3.ZERO
	## The paddle's normal and its speed along it through the contact.
	var normal: Vector3 = Vector3.FORWARD
	var speed: float = 0.0
	## Where the avatar stands for it.
	var avatar: Vector3 = Vector3.ZERO
	## The ball's predicted velocity there.
	var velocity_in: Vector3 = Vector3.ZERO


const _REPLAN_PERIOD_S: float = 0.05
const _HORIZON_S: float = 3.0
const _SAMPLE_S: float = 0.02
const _FOLLOW_THROUGH_S: float = 0.12
const _HISTORY_S: float = 0.6

## Seconds between seeing the ball and acting on it.
var reaction_delay_s: float = 0.12
## Error of the contact point it aims its paddle at, metres (the paddle radius is ~0.2).
var hit_error_m: float = 0.05
## Error of where it aims in the opponent's half, metres.
var aim_error_m: float = 0.35
## Top speed of its avatar, m/s.
var max_avatar_speed: float = 2.4
## Top speed of its paddle outside a swing, m/s.
var max_paddle_speed: float = 4.0
## Duration of the swing before the contact, seconds.
var swing_time_s: float = 0.12
## Fire at the opponent and place mines now and then.
var use_weapons: bool = true
## Mines placed per second on average while the ball is in the opponent's half.
var mine_rate_per_s: float = 0.1
## Seconds between shots at the least.
var fire_interval_s: float = 2.5
## Error of its aim with the gun, radians (a body is about 0.1 rad wide across the court).
var gun_error_rad: float = 0.08
## In beginner mode (no gravity, shots at the target).
var beginner: bool = false
## Play the ball to where the opponent's paddle waits (its workspace centre) instead of
## deep into its half or at its target: a ball that comes to the paddle is one a newcomer
## can return.
var plays_to_paddle: bool = false
## Speed of its shots, m/s: the ball's in beginner mode (at the target, or with
## [member plays_to_paddle] at the paddle), its speed along the floor for a lob that
## [member plays_to_paddle]. The servo's cap holds it too.
var shot_speed_m_per_s: float = 3.5
## Match time before which it keeps its weapons away (no gun, no mine), seconds: the first
## seconds of a match are for finding the paddle.
var weapons_from_s: float = 0.0
## The players it plays the ball to (one is picked per shot); the match keeps it to those
## still in. Default: the player across.
var targets: Array[int] = []

var _court: PongCourt = null
var _predictor: PongPredictor = null
var _reach: float = 0.5
var _rng: RandomNumberGenerator = RandomNumberGenerator.new()
var _seen_times: PackedFloat64Array = PackedFloat64Array()
var _seen_positions: PackedVector3Array = PackedVector3Array()
var _seen_velocities: PackedVector3Array = PackedVector3Array()
var _plan: Contact = null
var _replan_in: float = 0.0
var _resting_until: float = -1.0
var _next_fire: float = 0.0
# Mines owed: fills at the mine rate (each moment's share drawn at random) while the ball
# is away; a mine when it reaches one.
var _mine_credit: float = 0.0
var _aim_noise: Vector3 = Vector3.ZERO
var _hit_noise: Vector3 = Vector3.ZERO
var _target: int = -1
var _opponent_avatar: Vector3 = Vector3.ZERO
var _opponent_seen: bool = false


## [param reach]: how far the paddle may be from the avatar (the device workspace's
## radius times the workspace scale, metres).
func _init(p_player: int, court: PongCourt, reach: float, seed_value: int = 1) -> void:
	player = p_player
	_court = court
	_predictor = PongPredictor.new(court)
	_reach = reach
	_rng.seed = seed_value
	_mine_credit = _rng.randf()
	targets = [PongCourt.opponent_of(player)]
	intent.avatar = home()
	intent.normal = _rest_normal()


## Where the avatar waits: the middle of its half, at the workspace height.
func home() -> Vector3:
	return _court.clamp_avatar(player, _court.toward_back_wall(player, 0.6))


## The contact it aims at now (absolute time), or null.
func get_plan() -> Contact:
	return _plan


func update(now: float, dt: float, snapshot: PongState, opponent_avatar: Vector3) -> PongIntent:
	return decide(now, dt, snapshot.ball_position, snapshot.ball_velocity, opponent_avatar)


## The ball leaving its paddle ends the swing (the paddle keeps moving through the
## contact, which lasts tens of milliseconds).
func notice(event: PongEvent, now: float) -> void:
	if event.type == PongServoFacts.PongEventType.RELEASE and event.player == player:
		_resting_until = now + 0.25
		_plan = null


## Decides this update of [param dt] seconds at time [param now] from the ball's state;
## [param opponent_avatar] is where the other player stands. Returns [member intent].
func decide(
	now: float, dt: float, ball: Vector3, velocity: Vector3, opponent_avatar: Vector3
) -> PongIntent:
	_remember(now, ball, velocity)
	_opponent_avatar = opponent_avatar
	_opponent_seen = true
	_replan_in -= dt
	if _replan_in <= 0.0 and now >= _resting_until:
		_replan_in = _REPLAN_PERIOD_S
		_replan(now)
	intent.fire = false
	intent.place_mine = false
	var swinging: bool = _drive_paddle(now, dt)
	if not swinging:
		_walk(dt)
	_weapons(now, dt, ball, velocity, opponent_avatar)
	return intent


## The contact for a ball at [param position] with [param velocity] observed [param age]
## seconds ago, seen from an avatar at [param avatar] (time counted from now); null when it
## cannot meet the ball in its half within the horizon.
func plan_contact(position: Vector3, velocity: Vector3, age: float, avatar: Vector3) -> Contact:
	var g: float = 0.0 if beginner else _court.gravity
	var path: Array[PongPredictor.Segment] = _predictor.path(position, velocity, g, _HORIZON_S)
	var s: float = age + swing_time_s * 0.5
	while s < _HORIZON_S:
		var p: Vector3 = PongPredictor.position_at(path, s)
		var v: Vector3 = PongPredictor.velocity_at(path, s)
		if _can_meet(p, v, s - age, avatar):
			return _contact(p + _hit_noise, v, s - age)
		s += _SAMPLE_S
	return null


## The wanted velocity of the ball leaving its paddle at [param from] (before errors).
func wanted_velocity(from: Vector3) -> Vector3:
	var opponent: int = _target if targets.has(_target) else _pick_target()
	if plays_to_paddle:
		return _to_paddle(from, opponent)
	if beginner:
		# Along the wall: x for the walls of players 0 and 1, z for those of 2 and 3.
		var along: Vector3 = Vector3.RIGHT if opponent < 2 else Vector3.BACK
		var wall: Vector3 = _court.back_wall_centre(opponent)
		var lateral: float = clampf(
			_aim_noise.x, -_court.target_half_width, _court.target_half_width
		)
		var goal: Vector3 = wall + along * lateral
		goal.y = from.y
		return (goal - from).normalized() * minf(shot_speed_m_per_s, _court.max_ball_speed)
	var land: Vector3 = _court.toward_back_wall(opponent, 0.6)
	land.y = _court.ball_radius
	land += Vector3(_aim_noise.x, 0.0, _aim_noise.z)
	land = _court.clamp_inside(land, _court.ball_radius + 0.2)
	var distance: float = Vector2(land.x - from.x, land.z - from.z).length()
	var flight: float = clampf(distance / 4.0, 0.7, 1.3)
	return PongReferee.launch_velocity(from, land, _court.gravity, flight).limit_length(
		_court.max_ball_speed
	)


# A shot into [param opponent]'s workspace centre (the avatar the match reports for the
# player across, the home spot of another), off by the aim error sideways: in beginner
# mode straight, else a lob that comes down into it.
func _to_paddle(from: Vector3, opponent: int) -> Vector3:
	var across: bool = opponent == PongCourt.opponent_of(player) and _opponent_seen
	var paddle: Vector3 = (
		_opponent_avatar
		if across
		else _court.clamp_avatar(opponent, _court.toward_back_wall(opponent, 0.6))
	)
	paddle += PongCourt.side_rotation(opponent) * Vector3(_aim_noise.x, 0.0, 0.0)
	if beginner:
		paddle.y = from.y
		return (paddle - from).normalized() * minf(shot_speed_m_per_s, _court.max_ball_speed)
	var distance: float = Vector2(paddle.x - from.x, paddle.z - from.z).length()
	var flight: float = clampf(distance / shot_speed_m_per_s, 0.7, 1.6)
	return PongReferee.launch_velocity(from, paddle, _court.gravity, flight).limit_length(
		_court.max_ball_speed
	)


func _remember(now: float, ball: Vector3, velocity: Vector3) -> void:
	_seen_times.append(now)
	_seen_positions.append(ball)
	_seen_velocities.append(velocity)
	while _seen_times.size() > 2 and _seen_times[1] < now - _HISTORY_S:
		_seen_times.remove_at(0)
		_seen_positions.remove_at(0)
		_seen_velocities.remove_at(0)


func _replan(now: float) -> void:
	var index: int = 0
	for i: int in _seen_times.size():
		if _seen_times[i] <= now - reaction_delay_s:
			index = i
	var age: float = now - _seen_times[index]
	var plan: Contact = plan_contact(
		_seen_positions[index], _seen_velocities[index], age, intent.avatar
	)
	# Within the swing the plan is kept: the paddle is already on its way.
	if _plan != null and _plan.time - now < swing_time_s:
		return
	if plan == null:
		_plan = null
		return
	plan.time += now
	if _plan == null or absf(plan.time - _plan.time) > 0.15:
		_new_errors()
	_plan = plan


func _pick_target() -> int:
	if targets.is_empty():
		return PongCourt.opponent_of(player)
	if targets.size() == 1:
		return targets[0]
	return targets[_rng.randi_range(0, targets.size() - 1)]


func _new_errors() -> void:
	_target = _pick_target()
	_aim_noise = Vector3(_rng.randfn(0.0, aim_error_m), 0.0, _rng.randfn(0.0, aim_error_m))
	_hit_noise = Vector3(
		_rng.randfn(0.0, hit_error_m), _rng.randfn(0.0, hit_error_m), _rng.randfn(0.0, hit_error_m)
	)


func _can_meet(p: Vector3, v: Vector3, time_left: float, avatar: Vector3) -> bool:
	if _court.territory_at(p) != player or p.dot(-PongCourt.forward(player)) < 0.3:
		return false
	if v.dot(PongCourt.forward(player)) >= 0.0:
		return false
	if absf(p.y - _court.beginner_height) > _reach * 0.75:
		return false
	var stand: Vector3 = _court.clamp_avatar(player, p)
	var walk: float = maxf(avatar.distance_to(stand) - _reach * 0.5, 0.0)
	return walk / maxf(max_avatar_speed * speed_factor, 0.01) <= time_left - swing_time_s * 0.5


func _contact(point: Vector3, v_in: Vector3, time_left: float) -> Contact:
	var contact: Contact = Contact.new()
	var v_out: Vector3 = wanted_velocity(point)
	var delta: Vector3 = v_out - v_in
	contact.normal = delta.normalized() if delta.length() > 1e-3 else _rest_normal()
	contact.speed = (v_in.dot(contact.normal) + delta.length() / (1.0 + _court.restitution_paddle))
	contact.time = time_left
	contact.point = point
	contact.velocity_in = v_in
	# The avatar stands so that the swing is centred in the workspace.
	contact.avatar = _court.clamp_avatar(
		player, point - contact.normal * contact.speed * swing_time_s * 0.5
	)
	return contact


# Moves the paddle: toward the swing's start, through the swing, or back to rest. True
# while swinging (the avatar then stands still, so the paddle's world velocity is u n).
func _drive_paddle(now: float, dt: float) -> bool:
	var target: Vector3 = Vector3.ZERO
	var normal: Vector3 = _rest_normal()
	if _plan != null:
		var to_hit: float = _plan.time - now
		var n: Vector3 = _plan.normal
		var u: float = _plan.speed
		var point: Vector3 = _plan.point
		normal = n
		if to_hit <= swing_time_s and to_hit >= -_FOLLOW_THROUGH_S:
			var offset: Vector3 = (point - n * u * to_hit - intent.avatar).limit_length(_reach)
			intent.paddle_velocity = n * u
			intent.paddle_offset = offset
			intent.normal = n
			return true
		if to_hit < -_FOLLOW_THROUGH_S:
			_plan = null
		else:
			target = point - n * u * swing_time_s - _plan.avatar
	var step: Vector3 = (target.limit_length(_reach) - intent.paddle_offset).limit_length(
		max_paddle_speed * speed_factor * dt
	)
	intent.paddle_offset += step
	intent.paddle_velocity = step / maxf(dt, 1e-6)
	intent.normal = normal
	return false


func _walk(dt: float) -> void:
	var goal: Vector3 = home() if _plan == null else _plan.avatar
	var step: Vector3 = (goal - intent.avatar).limit_length(max_avatar_speed * speed_factor * dt)
	intent.avatar = _court.clamp_avatar(player, intent.avatar + step)
	intent.paddle_velocity += step / maxf(dt, 1e-6)


func _weapons(now: float, dt: float, ball: Vector3, velocity: Vector3, opponent: Vector3) -> void:
	var away: bool = velocity.dot(PongCourt.forward(player)) > 0.5
	var far: bool = _court.territory_at(ball) != player
	var armed: bool = use_weapons and now >= weapons_from_s
	intent.gun = armed and _plan == null and away and far
	if intent.gun:
		var muzzle: Vector3 = intent.avatar + intent.paddle_offset
		var body: Vector3 = Vector3(opponent.x, opponent.y * 0.6, opponent.z)
		var aim: Vector3 = (body - muzzle).normalized()
		intent.normal = aim
		if now >= _next_fire:
			var wobble: Vector3 = (
				Vector3(_rng.randfn(), _rng.randfn(), _rng.randfn()) * gun_error_rad
			)
			intent.normal = (aim + wobble).normalized()
			intent.fire = true
			_next_fire = now + fire_interval_s * _rng.randf_range(0.8, 1.6)
	# Mines come now and then, but never long overdue: with a coin toss per frame a player
	# whose ball was away for two seconds in a whole match could place none.
	if armed and far:
		_mine_credit += mine_rate_per_s * dt * _rng.randf_range(0.5, 1.5)
		if _mine_credit >= 1.0:
			_mine_credit -= 1.0
			intent.place_mine = true


func _rest_normal() -> Vector3:
	return (PongCourt.forward(player) + Vector3.UP * 0.4).normalized()
