extends PongController
## A first-time player, scripted, to measure whether a newcomer can rally: it keeps its
## paddle where it last saw the ball, seen late and placed shakily, and never plans,
## swings, spins, shoots or throws mines. Its paddle is kinematic (the game places it).
##
## Its numbers, each a newcomer's and not a player's who has learnt the game:
## [br]- it sees the ball [constant REACTION_S] late: a simple visual reaction takes about
## 0.2-0.25 s, and someone still finding the mouse and judging depth in a 3D view is slower;
## [br]- its hand wobbles by [constant WOBBLE_M] (standard deviation, world metres, x and y:
## about half the paddle's radius), a new wobble every [constant WOBBLE_PERIOD_S];
## [br]- its paddle moves at most [constant PADDLE_SPEED_M_PER_S] (a calm mouse: 0.5 m/s of
## stylus), its avatar walks at [constant WALK_SPEED_M_PER_S] (half the game's top speed:
## walking with the keys while aiming with the mouse);
## [br]- its paddle stays in the plane of its avatar, at the device scheme's resting tilt.

const REACTION_S: float = 0.3
const WOBBLE_M: float = 0.1
const WOBBLE_PERIOD_S: float = 0.2
const PADDLE_SPEED_M_PER_S: float = 2.5
const WALK_SPEED_M_PER_S: float = 1.2

var _court: PongCourt = null
var _reach: float = 0.5
var _rng: RandomNumberGenerator = RandomNumberGenerator.new()
var _seen_times: PackedFloat64Array = PackedFloat64Array()
var _seen_positions: PackedVector3Array = PackedVector3Array()
var _wobble: Vector3 = Vector3.ZERO
var _wobble_left_s: float = 0.0
var _home: Vector3 = Vector3.ZERO


func _init(p_player: int, court: PongCourt, reach: float, seed_value: int) -> void:
	player = p_player
	kinematic = true
	_court = court
	_reach = reach
	_rng.seed = seed_value
	_home = court.clamp_avatar(player, court.toward_back_wall(player, 0.6))
	intent.avatar = _home
	var rest: Vector3 = Basis(Vector3.RIGHT, PongHumanPlayer.REST_TILT_RAD) * Vector3.FORWARD
	intent.normal = PongCourt.side_rotation(player) * rest


func update(now: float, dt: float, snapshot: PongState, _opponent: Vector3) -> PongIntent:
	_seen_times.append(now)
	_seen_positions.append(snapshot.ball_position)
	while _seen_times.size() > 1 and _seen_times[1] <= now - REACTION_S:
		_seen_times.remove_at(0)
		_seen_positions.remove_at(0)
	_wobble_left_s -= dt
	if _wobble_left_s <= 0.0:
		_wobble_left_s = WOBBLE_PERIOD_S
		_wobble = Vector3(_rng.randfn(0.0, WOBBLE_M), _rng.randfn(0.0, WOBBLE_M), 0.0)
	# In its own frame: x across, y up, z its depth (the frame of its side of the court).
	var turn: Basis = PongCourt.side_rotation(player)
	var seen: Vector3 = turn.inverse() * _seen_positions[0] + _wobble
	var home: Vector3 = turn.inverse() * _home
	var before: Vector3 = intent.avatar + intent.paddle_offset
	var stand: Vector3 = _court.clamp_avatar(player, turn * Vector3(seen.x, 0.0, home.z))
	var walk: Vector3 = (stand - intent.avatar).limit_length(WALK_SPEED_M_PER_S * dt)
	intent.avatar = _court.clamp_avatar(player, intent.avatar + walk)
	var avatar: Vector3 = turn.inverse() * intent.avatar
	var want: Vector3 = turn * Vector3(seen.x - avatar.x, seen.y - avatar.y, 0.0)
	var move: Vector3 = (want.limit_length(_reach * 0.9) - intent.paddle_offset).limit_length(
		PADDLE_SPEED_M_PER_S * dt
	)
	intent.paddle_offset += move
	intent.paddle_velocity = (intent.avatar + intent.paddle_offset - before) / maxf(dt, 1e-6)
	return intent
