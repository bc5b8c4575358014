class_name PongCourt
extends RefCounted
## The court of Haptic Battle Pong as the game sees it. Everything the servo simulates
## (court size, ball, gravity, restitution, beginner plane, targets, effect strengths) is
## read once from the Pong renderer's settings ([code]PongServo.shared().get_settings()[/code],
## a [PongSettings]) and never repeated here; the game-side geometry that only the game uses
## (avatar body, mines) is defined here, once.
##
## World: metres, y up, floor y = 0, x in [-W, W], z in [-L, L]. Player 0 ("near") owns
## z >= 0, player 1 ("far") z < 0. With four players ([member players], the servo's
## [member PongSettings.players]) the court is square (W = L), player 2 sits at +x and player 3
## at -x, each side is its player's back wall and the territories are split by the
## diagonals (the servo's court.h; ties on a diagonal go to players 0 and 1).

## Radius of an avatar's body (bullet hits, mines under it), metres.
const AVATAR_BODY_RADIUS_M: float = 0.22
## Distance an avatar keeps from the walls and from the centre line, metres.
const AVATAR_MARGIN_M: float = 0.25

## How many players the court has: 2 or 4.
var players: int = 2
## Half the court's width W (x), metres (L with four players: the court is square).
var half_width: float = 0.0
## Half the court's length L (z), metres.
var half_length: float = 0.0
## Height of the walls and of the ceiling, metres.
var wall_height: float = 0.0
var ball_radius: float = 0.0
var paddle_radius: float = 0.0
## Gravity's magnitude, m/s² (0 in beginner mode is the servo's business).
var gravity: float = 0.0
var restitution_court: float = 0.0
var restitution_wall: float = 0.0
## Ball speed out / in off a paddle at rest (along its normal).
var restitution_paddle: float = 1.0
var max_ball_speed: float = 0.0
## Paddle metres per metre of stylus.
var workspace_scale: float = 1.0
## Height of the ball's plane in beginner mode; the avatars' workspace centres are held at
## this height too, so the beginner ball passes through the middle of every workspace.
var beginner_height: float = 0.0
## Half the width of the target on each back wall (beginner mode), metres.
var target_half_width: float = 0.0
## The settings read, for the effect strengths and durations.
var settings: PongSettings = PongSettings.new()


## The court of the Pong renderer's [param pong] settings.
static func from_settings(pong: PongSettings) -> PongCourt:
	var court: PongCourt = PongCourt.new()
	court.settings = pong
	court.players = pong.players
	court.half_width = pong.court_half_width_m
	court.half_length = pong.court_half_length_m
	court.wall_height = pong.wall_height_m
	court.ball_radius = pong.ball_radius_m
	court.paddle_radius = pong.paddle_radius_m
	court.gravity = pong.gravity_m_per_s2
	court.restitution_court = pong.restitution_court
	court.restitution_wall = pong.restitution_wall
	court.max_ball_speed = pong.max_ball_speed_m_per_s
	court.workspace_scale = pong.workspace_scale
	court.beginner_height = pong.beginner_height_m
	court.target_half_width = pong.beginner_target_half_width_m
	court.restitution_paddle = pong.restitution_paddle
	if court.players == 4:
		court.half_width = court.half_length
	return court


## The territory a point is in, in a court of [param count] players: 0 (near, z >= 0) or
## 1 (far); with four, 2 (x > |z|) or 3 (-x > |z|) too.
static func territory_of(point: Vector3, count: int = 2) -> int:
	if count != 4 or absf(point.z) >= absf(point.x):
		return 0 if point.z >= 0.0 else 1
	return 2 if point.x > 0.0 else 3


## The territory of [param point] in this court.
func territory_at(point: Vector3) -> int:
	return territory_of(point, players)


## The player across the court (0 and 1, 2 and 3).
static func opponent_of(player: int) -> int:
	return player ^ 1


## Player [param player]'s device frame in world axes: turned about y so that its forward
## (-z) points from its back wall at the centre (the servo's side_rotation): 0 degrees for
## player 0, 180 for player 1, +90 for player 2, -90 for player 3.
static func side_rotation(player: int) -> Basis:
	const TURNS: Array[float] = [0.0, PI, PI * 0.5, -PI * 0.5]
	return Basis(Vector3.UP, TURNS[player]) if player > 0 and player < 4 else Basis.IDENTITY


## The horizontal direction from [param player] toward the centre (-z for player 0).
static func forward(player: int) -> Vector3:
	return (side_rotation(player) * Vector3.FORWARD).round()


## z of [param player]'s back wall (players 0 and 1).
func back_wall_z(player: int) -> float:
	return half_length if player == 0 else -half_length


## The centre of [param player]'s back wall at floor level.
func back_wall_centre(player: int) -> Vector3:
	return -forward(player) * half_length


## The point [param fraction] of the way from the centre to [param player]'s back wall.
func toward_back_wall(player: int, fraction: float) -> Vector3:
	return back_wall_centre(player) * fraction


## Where an avatar may stand: [param point] kept inside [param player]'s territory, away
## from the walls and the territory's borders, at the workspace height.
func clamp_avatar(player: int, point: Vector3) -> Vector3:
	# In the player's own frame it stands at +z, looking toward -z.
	var local: Vector3 = side_rotation(player).inverse() * point
	var near: float = AVATAR_MARGIN_M
	var far: float = maxf(half_length - AVATAR_MARGIN_M, near)
	var depth: float = clampf(local.z if local.z > 0.0 else 0.0, near, far)
	var x_limit: float = maxf(half_width - AVATAR_MARGIN_M, 0.0)
	if players == 4:
		# The triangle z >= |x|: the margin off both diagonals.
		depth = maxf(depth, near * 2.0)
		x_limit = minf(x_limit, depth - near * sqrt(2.0))
	var clamped: Vector3 = Vector3(clampf(local.x, -x_limit, x_limit), 0.0, depth)
	var world: Vector3 = side_rotation(player) * clamped
	return Vector3(world.x, beginner_height, world.z)


## A point kept inside the walls by [param margin] metres (floor to ceiling).
func clamp_inside(point: Vector3, margin: float) -> Vector3:
	return Vector3(
		clampf(point.x, -half_width + margin, half_width - margin),
		clampf(point.y, margin, wall_height - margin),
		clampf(point.z, -half_length + margin, half_length - margin)
	)


## Whether [param point] on [param player]'s back wall is within its target (beginner).
func in_target(point: Vector3, player: int = 0) -> bool:
	var along: float = (side_rotation(player).inverse() * point).x
	return absf(along) <= target_half_width and point.y >= 0.0 and point.y <= wall_height
