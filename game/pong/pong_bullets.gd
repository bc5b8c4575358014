class_name PongBullets
extends RefCounted
## Bullets fired from a paddle held as a gun: each flies straight along the gun's axis (the
## paddle normal) at [constant SPEED_M_PER_S], without gravity, until it hits the other
## player's avatar (a vertical capsule from the floor to the workspace centre, radius
## [constant PongCourt.AVATAR_BODY_RADIUS_M]) or leaves the court (any wall, floor or
## ceiling). A player fires at most once per [constant COOLDOWN_S]. Bullets are the game's
## own (they never touch the ball).


## A bullet in flight.
class Bullet:
	extends RefCounted
	var owner: int = 0
	## The owner's shot number (0, 1, ...): with [member owner], the bullet's name on every
	## peer of a networked match.
	var id: int = 0
	var position: Vector3 = Vector3.ZERO
	var velocity: Vector3 = Vector3.ZERO

	func _init(p_owner: int, p_position: Vector3, p_velocity: Vector3, p_id: int = 0) -> void:
		owner = p_owner
		position = p_position
		velocity = p_velocity
		id = p_id


const SPEED_M_PER_S: float = 7.0
const COOLDOWN_S: float = 0.4
const RADIUS_M: float = 0.035

## Bullets in flight.
var flying: Array[Bullet] = []

var _cooldown: PackedFloat32Array = PackedFloat32Array([0.0, 0.0, 0.0, 0.0])
var _shots: PackedInt32Array = PackedInt32Array([0, 0, 0, 0])


## Whether [param player] may fire now.
func can_fire(player: int) -> bool:
	return _cooldown[player] <= 0.0


## Fires from [param origin] along [param axis] (any length); null while cooling down.
func fire(owner: int, origin: Vector3, axis: Vector3) -> Bullet:
	if not can_fire(owner) or axis.is_zero_approx():
		return null
	_cooldown[owner] = COOLDOWN_S
	var bullet: Bullet = Bullet.new(owner, origin, axis.normalized() * SPEED_M_PER_S, _shots[owner])
	_shots[owner] += 1
	flying.append(bullet)
	return bullet


## How many shots [param owner] has fired (its next shot's number).
func fired(owner: int) -> int:
	return _shots[owner]


## Counts each player's shots from [param counts] on (a player who rejoins a running match
## numbers its shots on from the match's).
func restore(counts: PackedInt64Array) -> void:
	for owner: int in mini(counts.size(), _shots.size()):
		_shots[owner] = maxi(_shots[owner], counts[owner])


## Adds [param owner]'s shot [param id], fired elsewhere (a networked match), at
## [param position] flying along [param direction] (no cooldown: the firer kept it).
func add(owner: int, id: int, position: Vector3, direction: Vector3) -> Bullet:
	var bullet: Bullet = Bullet.new(owner, position, direction.normalized() * SPEED_M_PER_S, id)
	_shots[owner] = maxi(_shots[owner], id + 1)
	flying.append(bullet)
	return bullet


## Removes [param owner]'s shot [param id] from the air; returns it, or null when it is
## not flying.
func take(owner: int, id: int) -> Bullet:
	for bullet: Bullet in flying:
		if bullet.owner == owner and bullet.id == id:
			flying.erase(bullet)
			return bullet
	return null


## Moves every bullet by [param dt] seconds. [param avatars] holds every avatar's workspace
## centre (a bullet hits the first other avatar it crosses). Returns the hits, each
## [code]{"owner", "id", "victim", "position", "direction"}[/code] (direction: the bullet's
## unit motion); hitting and leaving bullets are removed.
func advance(dt: float, court: PongCourt, avatars: Array[Vector3]) -> Array[Dictionary]:
	for player: int in _cooldown.size():
		_cooldown[player] = maxf(_cooldown[player] - dt, 0.0)
	var hits: Array[Dictionary] = []
	var kept: Array[Bullet] = []
	for bullet: Bullet in flying:
		var start: Vector3 = bullet.position
		bullet.position += bullet.velocity * dt
		var victim: int = _victim(bullet, start, avatars)
		if victim >= 0:
			(
				hits
				. append(
					{
						"owner": bullet.owner,
						"id": bullet.id,
						"victim": victim,
						"position": bullet.position,
						"direction": bullet.velocity.normalized(),
					}
				)
			)
		elif court.clamp_inside(bullet.position, 0.0) == bullet.position:
			kept.append(bullet)
	flying = kept
	return hits


# The first avatar other than the owner's that the bullet's step crosses, or -1.
func _victim(bullet: Bullet, start: Vector3, avatars: Array[Vector3]) -> int:
	for player: int in avatars.size():
		if player != bullet.owner and _crosses_body(start, bullet.position, avatars[player]):
			return player
	return -1


## Whether the segment [param from]-[param to] passes through the body of the avatar whose
## workspace centre is [param centre].
static func _crosses_body(from: Vector3, to: Vector3, centre: Vector3) -> bool:
	var foot: Vector3 = Vector3(centre.x, 0.0, centre.z)
	var closest: PackedVector3Array = Geometry3D.get_closest_points_between_segments(
		from, to, foot, centre
	)
	return closest[0].distance_to(closest[1]) <= PongCourt.AVATAR_BODY_RADIUS_M + RADIUS_M
