class_name PongMines
extends RefCounted
## The haptic mines. Each player has four, one of each kind, placed in this order: slow,
## heavy, remote, none (the paper's four: three haptic effects and one that only hurts
## and rumbles).
##
## Placement rule: avatars cannot cross the centre line, so a player "enters" the
## opponent's territory by throwing: the mine lands at the mirror image of the avatar's
## floor position in the centre line, (x, 0, z) -> (x, 0, -z), at least
## [constant MIN_NET_DISTANCE_M] beyond the line and inside the walls. Standing deep in
## one's own half mines the opponent's back court; standing at the line mines the front.
## A mine closer than [constant MIN_SPACING_M] to another one is refused (kept in hand).
##
## A mine goes off when its victim's avatar stands within [constant TRIGGER_RADIUS_M] of
## it (floor distance); it is then gone. Only the opponent's mines go off under an avatar.


## A mine on the court.
class Mine:
	extends RefCounted
	var owner: int = 0
	var kind: String = ""
	## On the floor (y = 0), in the opponent's territory.
	var position: Vector3 = Vector3.ZERO
	## The owner's mine number (0 to 3, the index of its kind in [constant KINDS]): with
	## [member owner], the mine's name on every peer of a networked match.
	var id: int = 0

	func _init(p_owner: int, p_kind: String, p_position: Vector3, p_id: int = 0) -> void:
		owner = p_owner
		kind = p_kind
		position = p_position
		id = p_id


## The kinds, in the order a player places them; the servo's effect kind of the same name.
const KINDS: Array[String] = ["slow", "heavy", "remote", "none"]
const MIN_NET_DISTANCE_M: float = 0.4
const MIN_SPACING_M: float = 0.5
## Floor distance from the avatar's centre that sets a mine off: the body's radius plus
## the mine's.
const TRIGGER_RADIUS_M: float = PongCourt.AVATAR_BODY_RADIUS_M + 0.13

## Mines on the court, not yet set off.
var placed: Array[Mine] = []

var _used: PackedInt32Array = PackedInt32Array([0, 0, 0, 0])


## How many mines [param player] still holds.
func left(player: int) -> int:
	return KINDS.size() - _used[player]


## The kind of [param player]'s next mine ("" when none is left).
func next_kind(player: int) -> String:
	return KINDS[_used[player]] if left(player) > 0 else ""


## Where [param owner]'s mine would land with its avatar at [param avatar] (the rule
## above).
static func landing_point(owner: int, avatar: Vector3, court: PongCourt) -> Vector3:
	if court.players == 4:
		# The same spot seen from the player across: its own frame's (x, depth).
		var local: Vector3 = PongCourt.side_rotation(owner).inverse() * avatar
		var spot: Vector3 = court.clamp_avatar(
			PongCourt.opponent_of(owner),
			PongCourt.side_rotation(PongCourt.opponent_of(owner)) * Vector3(local.x, 0.0, local.z)
		)
		return Vector3(spot.x, 0.0, spot.z)
	var depth: float = clampf(
		absf(avatar.z), MIN_NET_DISTANCE_M, court.half_length - TRIGGER_RADIUS_M
	)
	var limit: float = court.half_width - TRIGGER_RADIUS_M
	return Vector3(
		clampf(avatar.x, -limit, limit), 0.0, depth * signf(court.back_wall_z(1 - owner))
	)


## Places [param owner]'s next mine at [method landing_point]; null when none is left or
## the spot is taken.
func place(owner: int, avatar: Vector3, court: PongCourt) -> Mine:
	if left(owner) <= 0:
		return null
	var point: Vector3 = landing_point(owner, avatar, court)
	for mine: Mine in placed:
		if mine.position.distance_to(point) < MIN_SPACING_M:
			return null
	var mine: Mine = Mine.new(owner, next_kind(owner), point, _used[owner])
	_used[owner] += 1
	placed.append(mine)
	return mine


## Puts [param owner]'s mine number [param id] (kind [code]KINDS[id][/code]) at
## [param position], placed elsewhere (a networked match: the owner applied the rule);
## null when [param owner] has already used that number or it is not one.
func put(owner: int, id: int, position: Vector3) -> Mine:
	if id < _used[owner] or id >= KINDS.size():
		return null
	var mine: Mine = Mine.new(owner, KINDS[id], position, id)
	_used[owner] = id + 1
	placed.append(mine)
	return mine


## Removes [param owner]'s mine [param id] from the court; returns it, or null when it is
## not there.
func take(owner: int, id: int) -> Mine:
	for mine: Mine in placed:
		if mine.owner == owner and mine.id == id:
			placed.erase(mine)
			return mine
	return null


## The opponent's mine [param victim]'s avatar at [param avatar] stands on, removed from
## the court; null when none.
func step_on(victim: int, avatar: Vector3) -> Mine:
	var feet: Vector2 = Vector2(avatar.x, avatar.z)
	for mine: Mine in placed:
		if mine.owner == victim:
			continue
		if feet.distance_to(Vector2(mine.position.x, mine.position.z)) <= TRIGGER_RADIUS_M:
			placed.erase(mine)
			return mine
	return null
