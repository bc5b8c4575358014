class_name PongNetResume
extends RefCounted
## The match as it stands, for a player who rejoins it while it runs ([PongNetRejoins]): the
## server puts it in the start message it sends that player alone (each seat's health, the
## mines and shots each seat has used, the mines on the court and the bullets in flight); the
## client checks it as it checks each placed mine and fired shot, and takes it up. An
## ordinary start leaves all of it empty.


## Server: the match in [param match_node] as it stands, into [param start].
static func as_it_stands(match_node: PongMatch, start: PongNetStartMessage) -> void:
	start.health = match_node.rules.start_health
	for seat: int in start.owners.size():
		start.now_health.append(match_node.rules.get_health(seat))
		start.mines_used.append(match_node.mines.used(seat))
		start.bullets_fired.append(match_node.bullets.fired(seat))
	for mine: PongMines.Mine in match_node.mines.placed:
		var row: PongNetMineMessage = PongNetMineMessage.new()
		row.seat = mine.owner
		row.id = mine.id
		row.position = mine.position
		start.mines.append(row)
	var flying: Array[PongBullets.Bullet] = match_node.bullets.flying
	for bullet: PongBullets.Bullet in flying.slice(-PongNetFacts.NET_MAX_BULLETS):
		var row: PongNetBulletRow = PongNetBulletRow.new()
		row.seat = bullet.owner
		row.id = bullet.id
		row.position = bullet.position
		row.direction = bullet.velocity.normalized()
		start.bullets.append(row)


## Client: what is wrong with [param start] for a court of [param seats], or "".
static func check(start: PongNetStartMessage, seats: int) -> String:
	if start.owners.size() != seats:
		return "owners is not %d peer ids" % seats
	for counts: Array in [
		Array(start.now_health), Array(start.mines_used), Array(start.bullets_fired)
	]:
		if not counts.is_empty() and counts.size() != seats:
			return "%s is not one number per seat (%d)" % [counts, seats]
	# Each weapon by (seat, number), mines and bullets apart: listed once.
	var named: Dictionary[Vector2i, bool] = {}
	for row: PongNetMineMessage in start.mines:
		var reason: String = _check_weapon(row.seat, row.id, Array(start.mines_used), seats, "mine")
		if reason.is_empty() and named.has(Vector2i(row.seat, row.id)):
			reason = "mine %d of seat %d twice" % [row.id, row.seat]
		if reason.is_empty() and absf(row.position.y) > PongNetProtocol.FLOOR_TOLERANCE_M:
			reason = "a mine off the floor"
		if reason.is_empty() and PongCourt.territory_of(row.position, seats) == row.seat:
			reason = "a mine in its owner's own territory"
		if not reason.is_empty():
			return reason
		named[Vector2i(row.seat, row.id)] = true
	var flown: Dictionary[Vector2i, bool] = {}
	for row: PongNetBulletRow in start.bullets:
		var reason: String = _check_weapon(
			row.seat, row.id, Array(start.bullets_fired), seats, "bullet"
		)
		if reason.is_empty() and flown.has(Vector2i(row.seat, row.id)):
			reason = "bullet %d of seat %d twice" % [row.id, row.seat]
		if not reason.is_empty():
			return reason
		flown[Vector2i(row.seat, row.id)] = true
	return ""


## Client: [param play]'s match takes up the match as [param start] says it stands; nothing
## for an ordinary start.
static func take_up(play: PongNetPlay, start: PongNetStartMessage) -> void:
	var match_node: PongMatch = play.match_node
	match_node.rules.resume(start.now_health)
	var on_court: Array[PongMines.Mine] = []
	for row: PongNetMineMessage in start.mines:
		on_court.append(PongMines.Mine.new(row.seat, PongMines.KINDS[row.id], row.position, row.id))
	match_node.mines.restore(start.mines_used, on_court)
	match_node.bullets.restore(start.bullets_fired)
	play.weapons.take_up_shots(start.bullets_fired, start.bullets)


# A weapon [param id] of [param seat] is one of the [param used] that seat has used.
static func _check_weapon(seat: int, id: int, used: Array, seats: int, what: String) -> String:
	var reason: String = PongNetProtocol.check_seat(seat, seats)
	var limit: int = 0 if not reason.is_empty() or used.is_empty() else used[seat]
	if reason.is_empty() and id >= limit:
		reason = "%s %d of seat %d is not one it used" % [what, id, seat]
	return reason
