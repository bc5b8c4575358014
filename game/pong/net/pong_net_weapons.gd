class_name PongNetWeapons
extends PongWeaponReferee
## Bullets and mines in a networked match. The peer that drives a seat is the authority for
## that seat's actions (it fires, it places its mines) and for what happens to it (a bullet
## crosses its avatar, its avatar steps on a mine): it has the exact avatar, every other
## peer only a late copy. Three reliable messages (PongNetProtocol.CHANNEL_RELIABLE):
## [br]- a shot {seat, id, origin, direction, servo time}: every peer flies the bullet from
## where it would be by now (the message's age, as for the ball states);
## [br]- a mine {seat, id, position, kind}: every peer puts it where the owner's rule put it;
## [br]- a weapon hurt {victim, cause, weapon seat, weapon id}: the victim's peer decided it,
## every peer takes the health (the same way everywhere, as the master's floor hurts) and
## removes the bullet or mine.
## The firer's recoil and the victim's hit or mine effect stay in their own servo. A remote
## mine pulls the victim's hand toward the owner's stylus as the pose stream brings it, with
## its age (the servo's passivity rule keeps that coupling from gaining energy).
##
## Every received message is checked: the protocol's types and ranges, the sender owns the
## seat (a shot, a mine) or the victim (a hurt), numbers are not reused, a seat's shots keep
## its cooldown, a hurt names a weapon this peer knows, that could reach the victim (a mine
## in or next to its territory, a bullet whose flight crosses it; from the weapon's own
## message, so every peer judges alike) and hurts only once. A bad one is dropped and
## counted against its sender. A hurt may overtake its weapon: a client's message
## to all goes to each peer on its own until Godot has confirmed the node's path with all of
## them, so the victim's word (one leg) can come before a shot held up on the other leg by a
## lost packet. Such a hurt waits up to [constant PENDING_HURT_S] for its weapon.

## How long a hurt waits for the weapon it names, seconds (ENet's fifth retransmission on
## a 150 ms path comes after about 13 s; a weapon later than this is as good as lost).
const PENDING_HURT_S: float = 3.0
## A bullet's flight is followed in steps this long (less than a body's reach) and no
## farther than the court's diagonal allows, metres.
const REACH_STEP_M: float = 0.1
const REACH_LIMIT_M: float = 20.0

## Where this peer's messages go out.
var wire: PongNetWire = null
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
# Hurts waiting for their weapon, by its key: [sender, victim, cause, seat, id, wall time].
var _pending: Dictionary[int, Array] = {}
# Per seat: the last shot's number and its sender's servo time.
var _last_shot: PackedInt64Array = PackedInt64Array([-1, -1, -1, -1])
var _last_shot_s: PackedFloat64Array = PackedFloat64Array([-INF, -INF, -INF, -INF])
var _reject: Callable = Callable()
var _age_of: Callable = Callable()


## Follows [param p_match]; sends through [param p_wire]. [param p_reject]: Callable(sender,
## what, reason) drops a message with a log line and counts it; [param p_age_of]:
## Callable(sender, servo time) -> the age of a message, seconds.
func _init(
	p_wire: PongNetWire,
	p_match: PongMatch,
	p_authority: PongNetAuthority,
	p_reject: Callable,
	p_age_of: Callable
) -> void:
	wire = p_wire
	match_node = p_match
	authority = p_authority
	_reject = p_reject
	_age_of = p_age_of
	match_node.weapon_referee = self
	match_node.bullet_fired.connect(_on_bullet_fired)
	match_node.mine_placed.connect(_on_mine_placed)


## A peer judges the seats it drives.
func judges(seat: int) -> bool:
	return authority.owner_of(seat) == authority.my_id


## A hurt judged here: to every peer, and here through the same checks.
func hurt(
	_rules: PongRules, victim: int, cause: StringName, weapon_owner: int, weapon_id: int
) -> void:
	var args: Array = [victim, String(cause), weapon_owner, weapon_id]
	wire.send_all(&"_weapon_hurt", args)
	on_hurt(authority.my_id, victim, String(cause), weapon_owner, weapon_id)


## The report's part: {shots, mines, hurts}.
func to_dict() -> Dictionary:
	return {"shots": shots, "mines": mines_placed, "hurts": hurts}


# A weapon's name across seats and kinds.
static func _key(cause: String, seat: int, id: int) -> int:
	var kind: int = PongNetProtocol.WEAPON_CAUSES.find(cause)
	return (id * PongNetProtocol.MAX_SEATS + seat) * PongNetProtocol.WEAPON_CAUSES.size() + kind


func _on_bullet_fired(bullet: PongBullets.Bullet) -> void:
	if not judges(bullet.owner):
		return
	var direction: Vector3 = bullet.velocity.normalized()
	_take_shot(bullet.owner, bullet.id, match_node.snapshot.time_s, bullet.position, direction)
	wire.send_all(
		&"_bullet",
		[bullet.owner, bullet.id, bullet.position, direction, match_node.snapshot.time_s]
	)


func _on_mine_placed(mine: PongMines.Mine) -> void:
	if not judges(mine.owner):
		return
	_take_mine(mine)
	wire.send_all(&"_mine", [mine.owner, mine.id, mine.position, mine.kind])


func _take_shot(seat: int, id: int, time_s: float, origin: Vector3, direction: Vector3) -> void:
	_last_shot[seat] = id
	_last_shot_s[seat] = time_s
	_known[_key("bullet", seat, id)] = true
	_where[_key("bullet", seat, id)] = [origin, direction]
	shots.append([seat, id])


func _take_mine(mine: PongMines.Mine) -> void:
	_known[_key("mine", mine.owner, mine.id)] = true
	_where[_key("mine", mine.owner, mine.id)] = [mine.position]
	mines_placed.append([mine.owner, mine.id, mine.kind, mine.position.x, mine.position.z])


# --- received (PongNetWire's stubs, with the sender's id) ---


func on_bullet(
	sender: int, seat: Variant, id: Variant, origin: Variant, direction: Variant, time_s: Variant
) -> void:
	var reason: String = PongNetProtocol.check_bullet(
		seat, authority.owners.size(), id, origin, direction, time_s, match_node.court
	)
	if not reason.is_empty():
		_reject.call(sender, "bullet", reason)
		return
	var shooter: int = seat
	var shot: int = id
	var sent_at: float = time_s
	var from: Vector3 = origin
	var along: Vector3 = direction
	reason = _check_shot(sender, shooter, shot, sent_at)
	if not reason.is_empty():
		_reject.call(sender, "bullet", reason)
		return
	_take_shot(shooter, shot, sent_at, from, along)
	if _resolve_pending(_key("bullet", shooter, shot)):
		return  # It has already hit its victim.
	# Where it is by now: it flew on for the message's age.
	var measured: float = _age_of.call(sender, sent_at)
	var age: float = minf(measured, 0.5)
	var at: Vector3 = from + along * PongBullets.SPEED_M_PER_S * age
	if match_node.court.clamp_inside(at, 0.0) == at:
		match_node.bullet_fired.emit(match_node.bullets.add(shooter, shot, at, along))


func _check_shot(sender: int, seat: int, id: int, time_s: float) -> String:
	if authority.owner_of(seat) != sender:
		return "seat %d is not theirs" % seat
	if id <= _last_shot[seat]:
		return "bullet id %d of seat %d is not after %d" % [id, seat, _last_shot[seat]]
	var least: float = PongBullets.COOLDOWN_S * PongNetProtocol.COOLDOWN_SHARE
	if time_s - _last_shot_s[seat] < least:
		return "seat %d fired %.3f s after its last shot" % [seat, time_s - _last_shot_s[seat]]
	return ""


func on_mine(sender: int, seat: Variant, id: Variant, position: Variant, kind: Variant) -> void:
	var reason: String = PongNetProtocol.check_mine(
		seat, authority.owners.size(), id, position, kind, match_node.court
	)
	if not reason.is_empty():
		_reject.call(sender, "mine", reason)
		return
	var owner: int = seat
	var number: int = id
	var at: Vector3 = position
	if authority.owner_of(owner) != sender:
		reason = "seat %d is not theirs" % owner
	var mine: PongMines.Mine = null
	if reason.is_empty():
		mine = match_node.mines.put(owner, number, at)
		if mine == null:
			reason = "mine id %d of seat %d is used" % [number, owner]
	if not reason.is_empty():
		_reject.call(sender, "mine", reason)
		return
	_take_mine(mine)
	match_node.mine_placed.emit(mine)
	_resolve_pending(_key("mine", owner, number))


func on_hurt(sender: int, victim: Variant, cause: Variant, seat: Variant, id: Variant) -> void:
	var reason: String = PongNetProtocol.check_weapon_hurt(
		victim, authority.owners.size(), cause, seat, id
	)
	if not reason.is_empty():
		_reject.call(sender, "weapon hurt", reason)
		return
	var hurt_seat: int = victim
	var weapon_seat: int = seat
	var weapon_id: int = id
	var what: String = cause
	if authority.owner_of(hurt_seat) != sender:
		reason = "seat %d is not theirs to judge" % hurt_seat
	var key: int = _key(what, weapon_seat, weapon_id)
	if reason.is_empty() and not _known.has(key) and not _pending.has(key):
		_pending[key] = [sender, victim, cause, seat, id, _now_s()]
		return
	if reason.is_empty() and not _known.has(key):
		reason = "no %s %d of seat %d is known here" % [what, weapon_id, weapon_seat]
	if reason.is_empty() and _spent.has(key):
		reason = "%s %d of seat %d has already hurt" % [what, weapon_id, weapon_seat]
	if reason.is_empty() and not _could_reach(key, hurt_seat):
		reason = "%s %d of seat %d cannot reach seat %d" % [what, weapon_id, weapon_seat, hurt_seat]
	if not reason.is_empty():
		_reject.call(sender, "weapon hurt", reason)
		return
	_spent[key] = true
	var bullet: bool = what == "bullet"
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
		var hurt_args: Array = _pending[key]
		var since: float = hurt_args[5]
		if all or now - since > PENDING_HURT_S:
			_pending.erase(key)
			var what: String = "%s %d of seat %d" % [hurt_args[2], hurt_args[4], hurt_args[3]]
			_reject.call(hurt_args[0], "weapon hurt", "no %s came here" % what)


# Applies the hurt that waited for the weapon [param key] names; true if there was one.
func _resolve_pending(key: int) -> bool:
	if not _pending.has(key):
		return false
	var hurt_args: Array = _pending[key]
	_pending.erase(key)
	callv(&"on_hurt", hurt_args.slice(0, 5))
	return _spent.has(key)


static func _now_s() -> float:
	return Time.get_ticks_usec() / 1e6
