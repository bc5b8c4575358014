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
## A mine never lands on a standing player: one that would land within
## [constant CLEAR_OF_PLAYERS_M] of an avatar [method place] is told of lands beside it
## instead (across its side, the side the throw was on first), so mines are traps to walk
## into, not bombs on someone's head (two players at home on the centre line would
## otherwise get every mine under their feet). A mine closer than
## [constant MIN_SPACING_M] to another one is refused (kept in hand).
##
## A mine goes off when its victim's avatar stands within [constant TRIGGER_RADIUS_M] of
## it (floor distance); it is then gone. Only the opponent's mines go off under an avatar.

## [param mine] was on the court when this peer rejoined a running match ([method restore]).
signal restored(mine: Mine)


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
## What the players read for each kind (the servo's "none" is a mine that only hurts).
const KIND_NAMES: Dictionary[String, String] = {
	"slow": "slow", "heavy": "heavy", "remote": "remote-control", "none": "plain"
}
const MIN_NET_DISTANCE_M: float = 0.4
const MIN_SPACING_M: float = 0.5
## Floor distance from the avatar's centre that sets a mine off: the body's radius plus
## the mine's.
const TRIGGER_RADIUS_M: float = PongCourt.AVATAR_BODY_RADIUS_M + 0.13
## The least floor distance between a thrown mine and a standing avatar: a step beyond
## the trigger radius.
const CLEAR_OF_PLAYERS_M: float = TRIGGER_RADIUS_M + 0.25

## Mines on the court, not yet set off.
var placed: Array[Mine] = []

var _used: PackedInt32Array = PackedInt32Array([0, 0, 0, 0])


## How many mines [param player] still holds.
func left(player: int) -> int:
	return KINDS.size() - _used[player]


## What the players read for [param kind] (the kind itself when it has no name).
static func kind_name(kind: String) -> String:
	return KIND_NAMES.get(kind, kind)


## How many mines [param player] has placed (on the court or set off).
func used(player: int) -> int:
	return _used[player]


## The kind of [param player]'s next mine ("" when none is left).
func next_kind(player: int) -> String:
	return KINDS[_used[player]] if left(player) > 0 else ""


## Where [param owner]'s mine would land with its avatar at [param avatar] (the rule
## above).
static func landing_point(owner: int, avatar: Vector3, court: PongCourt) -> Vector3:
	var victim: int = PongCourt.opponent_of(owner)
	if court.players == 4:
		# The same spot seen from the player across: its own frame's (x, depth).
		var local: Vector3 = PongCourt.side_rotation(owner).inverse() * avatar
		return _inside(
			PongCourt.side_rotation(victim) * Vector3(local.x, 0.0, local.z), court, victim
		)
	return _inside(Vector3(avatar.x, 0.0, -avatar.z), court, victim)


## Places [param owner]'s next mine at [method landing_point], or beside the avatars of
## [param standing] it would land under (the rule above); null when none is left or every
## spot is taken.
func place(owner: int, avatar: Vector3, court: PongCourt, standing: Array[Vector3] = []) -> Mine:
	if left(owner) <= 0:
		return null
	var victim: int = PongCourt.opponent_of(owner)
	for point: Vector3 in _spots(landing_point(owner, avatar, court), standing, court, victim):
		if _free(point):
			var mine: Mine = Mine.new(owner, next_kind(owner), point, _used[owner])
			_used[owner] += 1
			placed.append(mine)
			return mine
	return null


# [param point], or when it is within [constant CLEAR_OF_PLAYERS_M] of one of
# [param standing], the spots beside that avatar across [param victim]'s side (the side the
# point is on first), those that are clear and inside the court.
static func _spots(
	point: Vector3, standing: Array[Vector3], court: PongCourt, victim: int
) -> Array[Vector3]:
	var under: int = standing.find_custom(
		func(avatar: Vector3) -> bool: return _floor_gap(point, avatar) < CLEAR_OF_PLAYERS_M
	)
	if under < 0:
		return [point]
	var feet: Vector3 = standing[under]
	var across: Vector3 = PongCourt.side_rotation(victim) * Vector3.RIGHT
	var first: float = 1.0 if across.dot(point - feet) >= 0.0 else -1.0
	var spots: Array[Vector3] = []
	for side: float in [first, -first]:
		var spot: Vector3 = _inside(feet + across * side * CLEAR_OF_PLAYERS_M, court, victim)
		var clear: bool = standing.all(
			func(other: Vector3) -> bool:
				return _floor_gap(spot, other) >= CLEAR_OF_PLAYERS_M - 1e-3
		)
		if clear:
			spots.append(spot)
	return spots


# [param point] on the floor of [param victim]'s territory where a mine may lie: with two
# players at least [constant MIN_NET_DISTANCE_M] beyond the centre line and a trigger radius
# inside the walls; with four where an avatar may stand.
static func _inside(point: Vector3, court: PongCourt, victim: int) -> Vector3:
	if court.players == 4:
		var spot: Vector3 = court.clamp_avatar(victim, point)
		return Vector3(spot.x, 0.0, spot.z)
	var depth: float = clampf(
		absf(point.z), MIN_NET_DISTANCE_M, court.half_length - TRIGGER_RADIUS_M
	)
	var limit: float = court.half_width - TRIGGER_RADIUS_M
	return Vector3(clampf(point.x, -limit, limit), 0.0, depth * signf(court.back_wall_z(victim)))


static func _floor_gap(a: Vector3, b: Vector3) -> float:
	return Vector2(a.x - b.x, a.z - b.z).length()


func _free(point: Vector3) -> bool:
	for mine: Mine in placed:
		if mine.position.distance_to(point) < MIN_SPACING_M:
			return false
	return true


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


## Sets the court as another peer has it (a player who rejoins a running match):
## [param used_counts] mines placed by each player, [param mines] lying on the court, each
## of them then [signal restored].
func restore(used_counts: PackedInt32Array, mines: Array[Mine]) -> void:
	for player: int in mini(used_counts.size(), _used.size()):
		_used[player] = clampi(used_counts[player], 0, KINDS.size())
	placed = mines.duplicate()
	for mine: Mine in placed:
		restored.emit(mine)


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
