class_name PongNetWeapons
extends PongWeaponReferee
## Bullets and mines in a networked match. The peer that drives a seat is the authority for
## that seat's actions (it fires, it places its mines) and for what happens to it (a bullet
## crosses its avatar, its avatar steps on a mine): it has the exact avatar, every other
## peer only a late copy. Three reliable messages:
## [br]- a shot ([PongNetBulletMessage]: seat, id, origin, direction, servo time): every peer
## flies the bullet from where it would be by now (the message's age, as for the ball states);
## [br]- a mine ([PongNetMineMessage]: seat, id, position): every peer puts it where the
## owner's rule put it;
## [br]- a weapon hurt ([PongNetWeaponHurtMessage]: victim, cause, weapon seat, weapon id): the
## victim's peer decided it, every peer takes the health (the same way everywhere, as the
## master's floor hurts) and removes the bullet or mine.
## The firer's recoil and the victim's hit or mine effect stay in their own servo. A remote
## mine pulls the victim's hand toward the owner's stylus as the pose stream brings it, with
## its age (the servo's passivity rule keeps that coupling from gaining energy).
##
## Every received message is checked: its fields by the schema ([PongNetRouter]), then against
## the match: seats of this court, positions in it, the sender owns the
## seat (a shot, a mine) or the victim (a hurt), numbers are not reused, a seat's shots keep
## its cooldown, a hurt names a weapon this peer knows, that could reach the victim (a mine
## in or next to its territory, a bullet whose flight crosses it; from the weapon's own
## message, so every peer judges alike) and hurts only once. A bad one is dropped and
## counted against its sender. A hurt may overtake its weapon: the two come from different
## peers, each in order on its own path (a client's forwarded by the server), so the
## victim's word can come before a shot held up on the shooter's path by a lost packet. Such a
## hurt waits up to [constant PENDING_HURT_S] for its weapon.

## How long a hurt waits for the weapon it names, seconds (ENet's fifth retransmission on
## a 150 ms path comes after about 13 s; a weapon later than this is as good as lost).
const PENDING_HURT_S: float = 3.0
## A bullet's flight is followed in steps this long (less than a body's reach) and no
## farther than the court's diagonal allows, metres.
const REACH_STEP_M: float = 0.1
const REACH_LIMIT_M: float = 20.0

## Where this peer's messages come and go.
var router: PongNetRouter = null
var match_node: PongMatch = null
var authority: PongNetAuthority = null
## [seat, id] of each shot taken (fired here or received), in order.
var shots: Array[Array] = []
## [seat, id, kind, x, z] of each mine taken, in order.
var mines_placed: Array[Array] = []
## [victim, cause, weapon seat, weapon id] of each weapon hurt applied, in order.
var hurts: Array[Array] = []

# Weapon keys (see _key) this peer knows of, and those that have hurt someone.
var _known: Dictionary[int, bool] = {}
# Where each known weapon was: a bullet's [origin, direction], a mine's [position].
var _where: Dictionary[int, Array] = {}
var _spent: Dictionary[int, bool] = {}
# Hurts waiting for their weapon, by its key: [sender, the hurt, wall time].
var _pending: Dictionary[int, Array] = {}
# Per seat: the last shot's number and its sender's servo time.
var _last_shot: PackedInt64Array = PackedInt64Array([-1, -1, -1, -1])
var _last_shot_s: PackedFloat64Array = PackedFloat64Array([-INF, -INF, -INF, -INF])
# Who fired each seat's last shot: its number and time (that peer's servo clock) are
# comparable only with the same peer's (the computer standing in, a player back or rejoined).
var _last_shooter: PackedInt64Array = PackedInt64Array([0, 0, 0, 0])
var _reject: Callable = Callable()
var _age_of: Callable = Callable()


## Follows [param p_match]; sends and takes through [param p_router]. [param p_reject]:
## Callable(sender, what, reason) drops a message with a log line and counts it;
## [param p_age_of]: Callable(sender, servo time) -> the age of a message, seconds.
func _init(
	p_router: PongNetRouter,
	p_match: PongMatch,
	p_authority: PongNetAuthority,
	p_reject: Callable,
	p_age_of: Callable
) -> void:
	router = p_router
	match_node = p_match
	authority = p_authority
	_reject = p_reject
	_age_of = p_age_of
	match_node.weapon_referee = self
	match_node.bullet_fired.connect(_on_bullet_fired)
	match_node.mine_placed.connect(_on_mine_placed)
	match_node.mines.restored.connect(_take_mine)
	router.handle(PongNetBulletMessage.SCHEMA_ID, on_bullet)
	router.handle(PongNetMineMessage.SCHEMA_ID, on_mine)
	router.handle(PongNetWeaponHurtMessage.SCHEMA_ID, on_hurt)


## A peer judges the seats it drives.
func judges(seat: int) -> bool:
	return authority.owner_of(seat) == authority.my_id


## A hurt judged here: to every peer, and here through the same checks.
func hurt(
	_rules: PongRules, victim: int, cause: StringName, weapon_owner: int, weapon_id: int
) -> void:
	var message: PongNetWeaponHurtMessage = PongNetWeaponHurtMessage.new()
	message.victim = victim
	message.cause = PongNetFacts.WEAPON_CAUSE_NAMES.find(String(cause)) as PongNetFacts.WeaponCause
	message.seat = weapon_owner
	message.id = weapon_id
	router.send_all(message)
	on_hurt(authority.my_id, message)


# A weapon's name across seats and kinds.
static func _key(cause: PongNetFacts.WeaponCause, seat: int, id: int) -> int:
	var causes: int = PongNetFacts.WEAPON_CAUSE_NAMES.size()
	return (id * PongNetProtocol.MAX_SEATS + seat) * causes + cause


func _on_bullet_fired(bullet: PongBullets.Bullet) -> void:
	if not judges(bullet.owner):
		return
	var shot: PongNetBulletMessage = PongNetBulletMessage.new()
	shot.seat = bullet.owner
	shot.id = bullet.id
	shot.origin = bullet.position
	shot.direction = bullet.velocity.normalized()
	shot.time_s = match_node.snapshot.time_s
	_take_shot(shot, authority.my_id)
	router.send_all(shot)


func _on_mine_placed(mine: PongMines.Mine) -> void:
	if not judges(mine.owner):
		return
	_take_mine(mine)
	var placed: PongNetMineMessage = PongNetMineMessage.new()
	placed.seat = mine.owner
	placed.id = mine.id
	placed.position = mine.position
	router.send_all(placed)


## A player who rejoins the match takes up each seat's shots fired so far ([param fired],
## by seat) and the bullets in flight ([param flying]): they fly here too, and a hurt that
## names one is of a weapon known here.
func take_up_shots(fired: PackedInt64Array, flying: Array[PongNetBulletRow]) -> void:
	for seat: int in mini(fired.size(), _last_shot.size()):
		_last_shot[seat] = fired[seat] - 1
	for row: PongNetBulletRow in flying:
		var key: int = _key(PongNetFacts.WeaponCause.BULLET, row.seat, row.id)
		_known[key] = true
		_where[key] = [row.position, row.direction]
		match_node.bullets.add(row.seat, row.id, row.position, row.direction)


func _take_shot(shot: PongNetBulletMessage, shooter: int) -> void:
	var key: int = _key(PongNetFacts.WeaponCause.BULLET, shot.seat, shot.id)
	_last_shot[shot.seat] = shot.id
	_last_shot_s[shot.seat] = shot.time_s
	_last_shooter[shot.seat] = shooter
	_known[key] = true
	_where[key] = [shot.origin, shot.direction]
	shots.append([shot.seat, shot.id])


func _take_mine(mine: PongMines.Mine) -> void:
	var key: int = _key(PongNetFacts.WeaponCause.MINE, mine.owner, mine.id)
	_known[key] = true
	_where[key] = [mine.position]
	mines_placed.append([mine.owner, mine.id, mine.kind, mine.position.x, mine.position.z])


# --- received, their fields checked (PongNetRouter): the checks against this match ---


func on_bullet(sender: int, shot: PongNetBulletMessage) -> void:
	var reason: String = _check_shot(sender, shot)
	if not reason.is_empty():
		_reject.call(sender, PongNetBulletMessage.LABEL, reason)
		return
	_take_shot(shot, sender)
	router.forward(sender, shot)
	if _resolve_pending(_key(PongNetFacts.WeaponCause.BULLET, shot.seat, shot.id)):
		return  # It has already hit its victim.
	# Where it is by now: it flew on for the message's age.
	var measured: float = _age_of.call(sender, shot.time_s)
	var age: float = clampf(measured, 0.0, 0.5)  # A stamp that does not fit: as if fresh.
	var at: Vector3 = shot.origin + shot.direction * PongBullets.SPEED_M_PER_S * age
	if match_node.court.clamp_inside(at, 0.0) == at:
		match_node.bullet_fired.emit(match_node.bullets.add(shot.seat, shot.id, at, shot.direction))


func _check_shot(sender: int, shot: PongNetBulletMessage) -> String:
	var seat: int = shot.seat
	var reason: String = PongNetProtocol.check_seat(seat, authority.owners.size())
	if reason.is_empty():
		var limit: Vector3 = PongNetProtocol.position_limit(match_node.court)
		reason = PongNetProtocol.check_box(shot.origin, limit, "origin")
	if not reason.is_empty():
		return reason
	if authority.owner_of(seat) != sender:
		return "seat %d is not theirs" % seat
	# A seat's numbers go on from its last shooter's: one standing in for a silent player may
	# reuse a number the player's game spent meanwhile on a shot that never arrived.
	if _last_shooter[seat] == sender and shot.id <= _last_shot[seat]:
		return "bullet id %d of seat %d is not after %d" % [shot.id, seat, _last_shot[seat]]
	var least: float = PongBullets.COOLDOWN_S * PongNetProtocol.COOLDOWN_SHARE
	if _last_shooter[seat] == sender and shot.time_s - _last_shot_s[seat] < least:
		return "seat %d fired %.3f s after its last shot" % [seat, shot.time_s - _last_shot_s[seat]]
	return ""


func on_mine(sender: int, placed: PongNetMineMessage) -> void:
	var reason: String = _check_mine(sender, placed)
	var mine: PongMines.Mine = null
	if reason.is_empty():
		mine = match_node.mines.put(placed.seat, placed.id, placed.position)
		if mine == null:
			reason = "mine id %d of seat %d is used" % [placed.id, placed.seat]
	if not reason.is_empty():
		_reject.call(sender, PongNetMineMessage.LABEL, reason)
		return
	_take_mine(mine)
	router.forward(sender, placed)
	match_node.mine_placed.emit(mine)
	_resolve_pending(_key(PongNetFacts.WeaponCause.MINE, placed.seat, placed.id))


# A mine lies on the floor inside the walls, in another seat's territory.
func _check_mine(sender: int, placed: PongNetMineMessage) -> String:
	var seats: int = authority.owners.size()
	var court: PongCourt = match_node.court
	var floor_box: Vector3 = Vector3(
		court.half_width, PongNetProtocol.FLOOR_TOLERANCE_M, court.half_length
	)
	var reason: String = PongNetProtocol.check_seat(placed.seat, seats)
	if reason.is_empty():
		reason = PongNetProtocol.check_box(placed.position, floor_box, "mine position")
	if reason.is_empty() and PongCourt.territory_of(placed.position, seats) == placed.seat:
		reason = "mine in its owner's own territory"
	if reason.is_empty() and authority.owner_of(placed.seat) != sender:
		reason = "seat %d is not theirs" % placed.seat
	return reason


func on_hurt(sender: int, hurt_message: PongNetWeaponHurtMessage) -> void:
	var seats: int = authority.owners.size()
	var hurt_seat: int = hurt_message.victim
	var weapon_seat: int = hurt_message.seat
	var weapon_id: int = hurt_message.id
	var what: String = PongNetFacts.WEAPON_CAUSE_NAMES[hurt_message.cause]
	var reason: String = PongNetProtocol.check_seat(hurt_seat, seats, "victim")
	if reason.is_empty():
		reason = PongNetProtocol.check_seat(weapon_seat, seats, "weapon seat")
	if reason.is_empty() and hurt_seat == weapon_seat:
		reason = "a weapon never hurts its owner"
	if reason.is_empty() and authority.owner_of(hurt_seat) != sender:
		reason = "seat %d is not theirs to judge" % hurt_seat
	var key: int = _key(hurt_message.cause, weapon_seat, weapon_id)
	if reason.is_empty() and not _known.has(key) and not _pending.has(key):
		_pending[key] = [sender, hurt_message, _now_s()]
		return
	if reason.is_empty() and not _known.has(key):
		reason = "no %s %d of seat %d is known here" % [what, weapon_id, weapon_seat]
	if reason.is_empty() and _spent.has(key):
		reason = "%s %d of seat %d has already hurt" % [what, weapon_id, weapon_seat]
	if reason.is_empty() and not _could_reach(key, hurt_seat):
		reason = "%s %d of seat %d cannot reach seat %d" % [what, weapon_id, weapon_seat, hurt_seat]
	if not reason.is_empty():
		_reject.call(sender, PongNetWeaponHurtMessage.LABEL, reason)
		return
	_spent[key] = true
	router.forward(sender, hurt_message)
	var bullet: bool = hurt_message.cause == PongNetFacts.WeaponCause.BULLET
	match_node.rules.hurt(hurt_seat, PongRules.CAUSE_BULLET if bullet else PongRules.CAUSE_MINE)
	hurts.append([hurt_seat, what, weapon_seat, weapon_id])
	if sender == authority.my_id:
		return  # The match shows its own hits.
	if bullet:
		var flying: PongBullets.Bullet = match_node.bullets.take(weapon_seat, weapon_id)
		var direction: Vector3 = flying.velocity.normalized() if flying != null else Vector3.ZERO
		var hit: Dictionary = {
			"owner": weapon_seat,
			"id": weapon_id,
			"victim": hurt_seat,
			"position": match_node.avatar_of(hurt_seat),
			"direction": direction,
		}
		match_node.bullet_hit.emit(hit)
		return
	var mine: PongMines.Mine = match_node.mines.take(weapon_seat, weapon_id)
	if mine != null:
		match_node.mine_exploded.emit(mine, hurt_seat)


## Whether the weapon [param key] could hurt [param victim]: a mine lies within its trigger
## radius of the victim's territory (an avatar never leaves its own), a bullet's flight
## through the court passes within a body's reach of it.
func _could_reach(key: int, victim: int) -> bool:
	var where: Array = _where.get(key, [])
	var seats: int = authority.owners.size()
	if where.size() == 1:
		var mine_at: Vector3 = where[0]
		return PongNetProtocol.near_territory(mine_at, victim, seats, PongMines.TRIGGER_RADIUS_M)
	if where.size() != 2:
		return false
	var origin: Vector3 = where[0]
	var direction: Vector3 = where[1]
	var reach: float = PongCourt.AVATAR_BODY_RADIUS_M + PongBullets.RADIUS_M
	var court: PongCourt = match_node.court
	var travelled: float = 0.0
	while travelled <= REACH_LIMIT_M:
		var at: Vector3 = origin + direction * travelled
		if PongNetProtocol.near_territory(at, victim, seats, reach):
			return true
		if court.clamp_inside(at, 0.0) != at:
			return false  # It left the court here.
		travelled += REACH_STEP_M
	return false


## Refuses the hurts that waited longer than [constant PENDING_HURT_S] for their weapon, or
## all of them with [param all] (the match is over).
func expire_pending(all: bool = false) -> void:
	var now: float = _now_s()
	for key: int in _pending.keys():
		var waiting: Array = _pending[key]
		var since: float = waiting[2]
		if all or now - since > PENDING_HURT_S:
			_pending.erase(key)
			var hurt_message: PongNetWeaponHurtMessage = waiting[1]
			var cause: String = PongNetFacts.WEAPON_CAUSE_NAMES[hurt_message.cause]
			var what: String = "%s %d of seat %d" % [cause, hurt_message.id, hurt_message.seat]
			_reject.call(waiting[0], PongNetWeaponHurtMessage.LABEL, "no %s came here" % what)


# Applies the hurt that waited for the weapon [param key] names; true if there was one.
func _resolve_pending(key: int) -> bool:
	if not _pending.has(key):
		return false
	var waiting: Array = _pending[key]
	_pending.erase(key)
	var sender: int = waiting[0]
	var hurt_message: PongNetWeaponHurtMessage = waiting[1]
	on_hurt(sender, hurt_message)
	return _spent.has(key)


static func _now_s() -> float:
	return Time.get_ticks_usec() / 1e6
