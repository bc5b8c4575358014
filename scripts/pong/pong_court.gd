class_name PongCourt
extends RefCounted
## The court of Haptic Battle Pong as the game sees it. Everything the servo simulates
## (court size, ball, gravity, restitution, beginner plane, targets, effect strengths) is
## read once from the servo's configuration ([code]Haptics.pong.get_config()[/code], the
## [code]"pong"[/code] section) and never repeated here; the game-side geometry that only
## the game uses (avatar body, mines) is defined here, once.
##
## World: metres, y up, floor y = 0, x in [-W, W], z in [-L, L]. Player 0 ("near") owns
## z >= 0, player 1 ("far") z < 0.

## Radius of an avatar's body (bullet hits, mines under it), metres.
const AVATAR_BODY_RADIUS_M: float = 0.22
## Distance an avatar keeps from the walls and from the centre line, metres.
const AVATAR_MARGIN_M: float = 0.25

## Half the court's width W (x), metres.
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
## The configuration section read, for the effect strengths and durations.
var config: Dictionary = {}


## The court from the servo's [code]"pong"[/code] configuration section. Missing keys are
## reported (the binding and this game disagree) and left at 0.
static func from_config(pong: Dictionary) -> PongCourt:
	var court: PongCourt = PongCourt.new()
	court.config = pong
	court.half_width = court.number("court_half_width_m")
	court.half_length = court.number("court_half_length_m")
	court.wall_height = court.number("wall_height_m")
	court.ball_radius = court.number("ball_radius_m")
	court.paddle_radius = court.number("paddle_radius_m")
	court.gravity = court.number("gravity_m_per_s2")
	court.restitution_court = court.number("restitution_court")
	court.restitution_wall = court.number("restitution_wall")
	court.max_ball_speed = court.number("max_ball_speed_m_per_s")
	court.workspace_scale = court.number("workspace_scale")
	court.beginner_height = court.number("beginner_height_m")
	court.target_half_width = court.number("beginner_target_half_width_m")
	court.restitution_paddle = court.number("restitution_paddle")
	return court


## A number of the configuration section; an error when it is missing.
func number(key: String) -> float:
	if not config.has(key):
		push_error("PongCourt: the servo's pong configuration has no '%s'." % key)
		return 0.0
	var value: float = config[key]
	return value


## The territory a point is in: 0 (near, z >= 0) or 1 (far).
static func territory_of(point: Vector3) -> int:
	return 0 if point.z >= 0.0 else 1


## The other player.
static func opponent_of(player: int) -> int:
	return 1 - player


## Player [param player]'s device frame in world axes: player 0's is the world's, player
## 1 faces the other way (rotated 180 degrees about y).
static func side_rotation(player: int) -> Basis:
	return Basis.IDENTITY if player == 0 else Basis(Vector3.UP, PI)


## The horizontal direction from [param player] toward the opponent (-z for player 0).
static func forward(player: int) -> Vector3:
	return Vector3.FORWARD if player == 0 else Vector3.BACK


## z of [param player]'s back wall.
func back_wall_z(player: int) -> float:
	return half_length if player == 0 else -half_length


## Where an avatar may stand: [param point] kept inside [param player]'s half, away from
## the walls and the centre line, at the workspace height.
func clamp_avatar(player: int, point: Vector3) -> Vector3:
	var x_limit: float = maxf(half_width - AVATAR_MARGIN_M, 0.0)
	var near: float = AVATAR_MARGIN_M
	var far: float = maxf(half_length - AVATAR_MARGIN_M, near)
	var depth: float = clampf(absf(point.z) if _on_side(player, point.z) else 0.0, near, far)
	return Vector3(
		clampf(point.x, -x_limit, x_limit), beginner_height, depth * signf(back_wall_z(player))
	)


## A point kept inside the walls by [param margin] metres (floor to ceiling).
func clamp_inside(point: Vector3, margin: float) -> Vector3:
	return Vector3(
		clampf(point.x, -half_width + margin, half_width - margin),
		clampf(point.y, margin, wall_height - margin),
		clampf(point.z, -half_length + margin, half_length - margin)
	)


## Whether [param point] on [param player]'s back wall is within its target (beginner).
func in_target(point: Vector3) -> bool:
	return absf(point.x) <= target_half_width and point.y >= 0.0 and point.y <= wall_height


## The wall name a back-wall event of the servo uses for [param player]'s back wall.
static func back_wall_name(player: int) -> String:
	return "back_near" if player == 0 else "back_far"


func _on_side(player: int, z: float) -> bool:
	return territory_of(Vector3(0.0, 0.0, z)) == player and not is_zero_approx(z)
