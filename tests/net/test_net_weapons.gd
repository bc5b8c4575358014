extends "res://tests/net/net_play_suite.gd"
## Bullets and mines in a networked match, without sockets: the messages' checks, and the
## authority rules of [PongNetWeapons] on one peer of a real stepped match (the host, seat
## 0; the client, peer 42, drives seat 1). Received messages reach it as bytes through its
## router with their sender's id; what this peer sends is recorded.

const BULLET: PongNetFacts.WeaponCause = PongNetFacts.WeaponCause.BULLET
const MINE: PongNetFacts.WeaponCause = PongNetFacts.WeaponCause.MINE


func _open() -> PongNetWeapons:
	var play: PongNetPlay = _open_play()
	return play.weapons if play != null else null


# --- the checks ---


func test_good_weapon_messages_decode_as_they_were_sent() -> void:
	var shot: PongNetBulletMessage = _bullet(1, 0, Vector3(0, 1, -2), Vector3.UP, 3.0)
	var back: PongNetBulletMessage = PongNetBulletMessage.decode(shot.encode())
	assert_not_null(back, HapticsWireReader.last_error)
	if back != null:
		assert_eq(
			[back.seat, back.id, back.origin, back.direction], [1, 0, shot.origin, Vector3.UP]
		)
	var mine: PongNetMineMessage = _mine(1, 2, Vector3(0.5, 0, 1.5))
	assert_not_null(PongNetMineMessage.decode(mine.encode()), HapticsWireReader.last_error)
	var hurt: PongNetWeaponHurtMessage = _weapon_hurt(0, BULLET, 1, 7)
	assert_not_null(PongNetWeaponHurtMessage.decode(hurt.encode()), HapticsWireReader.last_error)


# Why [param message]'s bytes decode to nothing ("" when they decode).
func _why_not(message: PongNetMessage) -> String:
	var decoder: Callable = PongNetFacts.message_decoders()[message.encode().decode_u32(0)]
	return "" if decoder.call(message.encode()) != null else HapticsWireReader.last_error


func test_weapon_messages_outside_the_schemas_limits_do_not_decode() -> void:
	var at: Vector3 = Vector3(0, 1, -2)
	var up: Vector3 = Vector3.UP
	assert_true(_why_not(_bullet(4, 0, at, up, 3.0)).contains("seat: 4 is outside"))
	var far: String = _why_not(_bullet(1, 0, Vector3(0, 1, 199), up, 3.0))
	assert_true(far.contains("origin: length"), far)
	assert_true(_why_not(_bullet(1, 0, at, up * 2.0, 3.0)).contains("direction: length 2"))
	assert_true(_why_not(_bullet(1, 0, at, Vector3.ZERO, 3.0)).contains("direction: zero"))
	assert_true(_why_not(_bullet(1, 0, at, Vector3(NAN, 0, 0), 3.0)).contains("not finite"))
	assert_true(_why_not(_bullet(1, 0, at, up, -1.0)).contains("time_s"))
	var id: int = PongNetFacts.NET_MAX_WEAPON_ID + 1
	assert_true(_why_not(_bullet(1, id, at, up, 3.0)).contains("id: %d is outside" % id))
	assert_true(_why_not(_mine(1, 4, Vector3(0.5, 0, 1.5))).contains("id: 4 is outside"))
	var hurt: PackedByteArray = _weapon_hurt(0, MINE, 1, 0).encode()
	hurt[5] = 2
	assert_null(PongNetWeaponHurtMessage.decode(hurt))
	assert_true(HapticsWireReader.last_error.contains("cause: 2 is none of the 2"))


func test_weapon_messages_that_cannot_be_in_this_match_are_refused() -> void:
	var weapons: PongNetWeapons = _open()
	if weapons == null:
		return
	var spot: Vector3 = Vector3(0.5, 0, 1.5)
	_receive(CLIENT, _bullet(2, 0, Vector3(0, 1, -2), Vector3.UP, 3.0))
	_receive(CLIENT, _bullet(1, 0, Vector3(0, 1, 9), Vector3.UP, 3.0))
	assert_eq(_refused("bullet"), 2, "a seat of no two-seat court, outside the court")
	_receive(CLIENT, _mine(1, 0, spot + Vector3.UP))
	_receive(CLIENT, _mine(1, 0, Vector3(0, 0, 9)))
	_receive(CLIENT, _mine(0, 0, spot))
	assert_eq(_refused("mine"), 3, "off the floor, outside the court, the owner's territory")
	_receive(CLIENT, _weapon_hurt(1, MINE, 1, 0))
	_receive(CLIENT, _weapon_hurt(2, MINE, 1, 0))
	assert_eq(_refused("weapon hurt"), 2, "its owner, a seat of no two-seat court")
	assert_true(weapons.shots.is_empty() and weapons.mines_placed.is_empty())


# --- the authority rules on one peer ---


func test_a_shot_is_taken_once_from_its_seats_peer_and_keeps_the_cooldown() -> void:
	var weapons: PongNetWeapons = _open()
	if weapons == null:
		return
	var bullets: PongBullets = _play.match_node.bullets
	var origin: Vector3 = Vector3(0.0, 1.0, -2.0)
	_receive(HOST, _bullet(1, 0, origin, Vector3.BACK, 10.0))
	assert_eq(bullets.flying.size(), 0, "not from the host: seat 1 is the client's")
	_receive(CLIENT, _bullet(1, 0, origin, Vector3.BACK, 10.0))
	assert_eq(bullets.flying.size(), 1, "from the seat's peer: it flies")
	var flying: PongBullets.Bullet = bullets.flying[0]
	assert_eq([flying.owner, flying.id], [1, 0])
	# It flew on for the message's age (no round trip measured here: at least 0).
	assert_true(flying.position.z >= origin.z and flying.position.z - origin.z < 3.6)
	_receive(CLIENT, _bullet(1, 0, origin, Vector3.BACK, 11.0))
	_receive(CLIENT, _bullet(1, 1, origin, Vector3.BACK, 10.1))
	assert_eq(bullets.flying.size(), 1, "a reused number and a shot within the cooldown are not")
	_receive(CLIENT, _bullet(1, 1, origin, Vector3.BACK, 10.5))
	assert_eq(bullets.flying.size(), 2, "the next shot after the cooldown is")
	assert_eq(_refused("bullet"), 3)
	assert_eq(weapons.shots, [[1, 0], [1, 1]])


func test_a_seats_new_peer_keeps_the_cooldown_and_the_numbers_of_its_own() -> void:
	if _open() == null:
		return
	var bullets: PongBullets = _play.match_node.bullets
	var origin: Vector3 = Vector3(0.0, 1.0, -2.0)
	_receive(CLIENT, _bullet(1, 0, origin, Vector3.BACK, 40.0))
	# Another peer drives the seat now (the computer standing in, a player rejoined on a new
	# connection): its servo clock is its own, and a number the last peer spent on a shot
	# that never arrived elsewhere is no reuse of its own.
	var again: int = 43
	_play.authority.owners[1] = again
	_receive(again, _bullet(1, 0, origin, Vector3.BACK, 0.5))
	assert_eq(bullets.flying.size(), 2, "its first shot: neither its number nor its clock clash")
	_receive(again, _bullet(1, 0, origin, Vector3.BACK, 1.5))
	_receive(again, _bullet(1, 1, origin, Vector3.BACK, 0.6))
	assert_eq(bullets.flying.size(), 2, "its own reused number, and its next within the cooldown")
	assert_eq(_refused("bullet"), 2)


func test_a_mine_is_put_where_its_owner_put_it_once_and_only_from_its_peer() -> void:
	var weapons: PongNetWeapons = _open()
	if weapons == null:
		return
	var mines: PongMines = _play.match_node.mines
	var spot: Vector3 = Vector3(0.3, 0.0, 1.5)
	_receive(HOST, _mine(1, 0, spot))
	assert_eq(mines.placed.size(), 0, "not from the host")
	_receive(CLIENT, _mine(1, 2, spot))
	assert_eq(mines.placed.size(), 1, "the client's third mine, where it put it")
	assert_eq(mines.placed[0].position, spot)
	assert_eq(mines.next_kind(1), "none", "its earlier numbers are spent")
	assert_eq(mines.placed[0].kind, "remote", "its kind is its number's")
	_receive(CLIENT, _mine(1, 1, spot + Vector3.RIGHT))
	_receive(CLIENT, _mine(1, 2, spot + Vector3.RIGHT))
	assert_eq(mines.placed.size(), 1, "numbers are not reused")
	assert_eq(_refused("mine"), 3)


func test_a_weapon_hurt_counts_once_only_from_the_victims_peer_for_a_known_weapon() -> void:
	var weapons: PongNetWeapons = _open()
	if weapons == null:
		return
	var rules: PongRules = _play.match_node.rules
	var mines: PongMines = _play.match_node.mines
	# The host's own mine (placed here) in the client's half.
	var mine: PongMines.Mine = mines.place(0, Vector3(0.3, 1.0, 1.5), _play.match_node.court)
	_play.match_node.mine_placed.emit(mine)
	assert_eq(_router.sent_of(PongNetMineMessage.SCHEMA_ID).size(), 1, "the host's mine went out")
	_receive(HOST, _weapon_hurt(1, MINE, 0, mine.id))
	assert_eq(rules.get_health(1), 99, "the host does not judge the client's seat")
	_receive(CLIENT, _weapon_hurt(1, MINE, 0, mine.id + 1))
	assert_eq(rules.get_health(1), 99, "an unknown mine (waiting for it)")
	_receive(CLIENT, _weapon_hurt(1, MINE, 0, mine.id))
	var lost: int = PongRules.DAMAGE[PongRules.CAUSE_MINE]
	assert_eq(rules.get_health(1), 99 - lost, "the client's word on its seat")
	assert_eq(mines.placed.size(), 0, "the mine went off here too")
	_receive(CLIENT, _weapon_hurt(1, MINE, 0, mine.id))
	assert_eq(rules.get_health(1), 99 - lost, "a mine hurts once")
	assert_eq(_refused("weapon hurt"), 2)
	weapons.expire_pending(true)
	assert_eq(_refused("weapon hurt"), 3, "the unknown mine never came")
	assert_eq(weapons.hurts, [[1, "mine", 0, mine.id]])


func test_a_hurt_that_overtakes_its_weapon_waits_for_it() -> void:
	var weapons: PongNetWeapons = _open()
	if weapons == null:
		return
	var match_node: PongMatch = _play.match_node
	# A third peer: it hears the host's word on seat 0 before the client's weapons.
	var third: PongNetAuthority = PongNetAuthority.new(7, PackedInt64Array([HOST, CLIENT]))
	_play.authority = third
	weapons.authority = third
	_receive(HOST, _weapon_hurt(0, MINE, 1, 0))
	_receive(HOST, _weapon_hurt(0, BULLET, 1, 0))
	assert_eq(match_node.rules.get_health(0), 99, "not before the weapons are known")
	assert_eq(_refused("weapon hurt"), 0, "waiting, not refused")
	_receive(CLIENT, _mine(1, 0, Vector3(0.3, 0.0, 1.5)))
	var after_mine: int = 99 - PongRules.DAMAGE[PongRules.CAUSE_MINE]
	assert_eq(match_node.rules.get_health(0), after_mine, "the mine came: it went off")
	assert_eq(match_node.mines.placed.size(), 0)
	var host_avatar: Vector3 = match_node.avatar_of(0)
	_receive(CLIENT, _bullet(1, 0, host_avatar + Vector3(0.0, 0.0, -1.0), Vector3.BACK, 10.0))
	var lost: int = PongRules.DAMAGE[PongRules.CAUSE_BULLET]
	assert_eq(match_node.rules.get_health(0), after_mine - lost, "the bullet came: it hit")
	assert_true(match_node.bullets.flying.is_empty(), "a bullet that has hit does not fly")
	assert_eq(weapons.hurts, [[0, "mine", 1, 0], [0, "bullet", 1, 0]])
	weapons.expire_pending(true)
	assert_eq(_refused("weapon hurt"), 0, "nothing left waiting")


func test_only_the_seats_this_peer_drives_are_judged_here() -> void:
	var weapons: PongNetWeapons = _open()
	if weapons == null:
		return
	var match_node: PongMatch = _play.match_node
	assert_true(weapons.judges(0))
	assert_false(weapons.judges(1))
	# A client's bullet through the host's avatar: judged here, told to everyone.
	var host_avatar: Vector3 = match_node.avatar_of(0)
	var from: Vector3 = host_avatar + Vector3(0.0, 0.0, -0.5)
	_receive(CLIENT, _bullet(1, 0, from, Vector3.BACK, 10.0))
	# The host's bullet through the client's avatar: not judged here (no hurt).
	var client_avatar: Vector3 = match_node.avatar_of(1)
	var bullet: PongBullets.Bullet = match_node.bullets.fire(
		0, client_avatar + Vector3(0.0, 0.0, 0.5), Vector3.FORWARD
	)
	match_node.bullet_fired.emit(bullet)
	match_node.run_until(func() -> bool: return match_node.bullets.flying.is_empty(), 1.0)
	var hurts: Array[PongNetMessage] = _router.sent_of(PongNetWeaponHurtMessage.SCHEMA_ID)
	assert_eq(hurts.size(), 1, "only the hit on seat 0")
	if hurts.size() == 1:
		var hit: PongNetWeaponHurtMessage = hurts[0]
		assert_eq([hit.victim, hit.cause, hit.seat, hit.id], [0, BULLET, 1, 0])
	var lost: int = PongRules.DAMAGE[PongRules.CAUSE_BULLET]
	assert_eq(match_node.rules.get_health(0), 99 - lost)
	assert_eq(match_node.rules.get_health(1), 99, "seat 1's peer decides its own")
	var shots: Array[PongNetMessage] = _router.sent_of(PongNetBulletMessage.SCHEMA_ID)
	assert_eq(shots.size(), 1, "the host's shot went out, the client's not back")


func test_a_player_who_rejoins_learns_the_mines_on_the_court_and_what_each_seat_used() -> void:
	if _open() == null:
		return
	var match_node: PongMatch = _play.match_node
	# The host's first mine lands in the client's half; the client's second in the host's.
	var mine: PongMines.Mine = match_node.mines.place(0, Vector3(0.3, 1.0, 1.5), match_node.court)
	match_node.mine_placed.emit(mine)
	_receive(CLIENT, _mine(1, 1, Vector3(0.3, 0.0, 1.5)))
	# The client's first two shots: one still flies.
	_receive(CLIENT, _bullet(1, 0, Vector3(0.0, 1.0, 2.0), Vector3.FORWARD, 10.0))
	_receive(CLIENT, _bullet(1, 1, Vector3(0.0, 1.0, 2.0), Vector3.FORWARD, 10.5))
	match_node.bullets.take(1, 0)
	var start: PongNetStartMessage = PongNetStartMessage.new()
	start.owners = PackedInt64Array([HOST, CLIENT])
	PongNetResume.as_it_stands(match_node, start)
	var sent: PongNetStartMessage = PongNetStartMessage.decode(start.encode())
	assert_not_null(sent, "the start decodes")
	assert_eq(sent.mines_used, PackedInt32Array([1, 2]), "each seat's mines used")
	assert_eq(sent.bullets_fired, PackedInt64Array([0, 2]), "each seat's shots fired")
	assert_eq([sent.bullets.size(), sent.bullets[0].seat, sent.bullets[0].id], [1, 1, 1])
	assert_eq(sent.now_health, PackedInt32Array([99, 99]))
	var rows: Array = sent.mines.map(func(r: PongNetMineMessage) -> Array: return [r.seat, r.id])
	assert_eq(rows, [[0, 0], [1, 1]], "both mines on the court")
	assert_eq(PongNetResume.check(sent, 2), "", "an honest server's start")
	# A start that cannot be: each refused with why.
	var never: PongNetMineMessage = _mine(1, 2, Vector3(0.3, 0.0, 1.0))
	var own: PongNetMineMessage = _mine(1, 0, Vector3(0.3, 0.0, -1.0))
	var aloft: PongNetMineMessage = _mine(0, 0, Vector3(0.3, 0.5, -1.5))
	var cases: Array[Array] = [
		[[never], "not one it used"],
		[[sent.mines[1], sent.mines[1]], "twice"],
		[[own], "its owner's own territory"],
		[[aloft], "off the floor"],
	]
	var unfired: PongNetBulletRow = PongNetBulletRow.new()
	unfired.seat = 1
	unfired.id = 2
	unfired.direction = Vector3.FORWARD
	cases.append([[unfired], "bullet 2 of seat 1 is not one it used"])
	cases.append([[sent.bullets[0], sent.bullets[0]], "bullet 1 of seat 1 twice"])
	for case: Array in cases:
		var bad: PongNetStartMessage = PongNetStartMessage.decode(start.encode())
		var rows_sent: Array = case[0]
		var expected: String = case[1]
		if rows_sent[0] is PongNetBulletRow:
			bad.bullets.assign(rows_sent)
		else:
			bad.mines.assign(rows_sent)
		var why: String = PongNetResume.check(bad, 2)
		assert_true(why.contains(expected), "%s: %s" % [expected, why])
	sent.mines_used = PackedInt32Array([1, 2, 0])
	var reason: String = PongNetResume.check(sent, 2)
	assert_true(reason.contains("one number per seat"), "three seats' counts: %s" % reason)


func test_a_player_who_rejoins_takes_up_the_mines_and_sends_none_of_them_again() -> void:
	var weapons: PongNetWeapons = _open()
	if weapons == null:
		return
	var match_node: PongMatch = _play.match_node
	var shown: Array[PongMines.Mine] = []
	match_node.mines.restored.connect(shown.append)
	var start: PongNetStartMessage = PongNetStartMessage.new()
	start.owners = PackedInt64Array([HOST, CLIENT])
	start.mines_used = PackedInt32Array([2, 1])
	start.bullets_fired = PackedInt64Array([7, 3])
	var flying: PongNetBulletRow = PongNetBulletRow.new()
	flying.seat = 0
	flying.id = 6
	flying.position = Vector3(0.0, 1.0, 0.5)
	flying.direction = Vector3.FORWARD  # Toward the client's half.
	start.bullets = [flying]
	start.mines = [_mine(0, 1, Vector3(0.3, 0.0, -1.5)), _mine(1, 0, Vector3(0.3, 0.0, 1.5))]
	PongNetResume.take_up(_play, start)
	var mines: PongMines = match_node.mines
	assert_eq([mines.placed.size(), shown.size()], [2, 2], "both on the court and shown")
	assert_eq([mines.next_kind(0), mines.next_kind(1)], ["remote", "heavy"], "the next of each")
	assert_eq(_router.sent_of(PongNetMineMessage.SCHEMA_ID).size(), 0, "none sent again")
	var shots: Array[int] = [match_node.bullets.fired(0), match_node.bullets.fired(1)]
	assert_eq(shots, [7, 3], "each seat's shots are numbered on from the match's")
	assert_eq(match_node.bullets.flying.size(), 1, "the host's bullet flies here too")
	# The client's word that it hit: a bullet known here, counted at once.
	_receive(CLIENT, _weapon_hurt(1, BULLET, 0, 6))
	var shot: int = PongRules.DAMAGE[PongRules.CAUSE_BULLET]
	assert_eq(match_node.rules.get_health(1), 99 - shot, "a known bullet, not one waited for")
	# This peer knows the host's mine: the client's word that it went off counts at once.
	_receive(CLIENT, _weapon_hurt(1, MINE, 0, 1))
	var lost: int = PongRules.DAMAGE[PongRules.CAUSE_MINE]
	assert_eq(match_node.rules.get_health(1), 99 - shot - lost, "a known mine, not waited for")
	assert_eq(mines.placed.size(), 1)
	# The client's numbers go on from its count: its first is spent, its second is new.
	_receive(CLIENT, _mine(1, 0, Vector3(-0.5, 0.0, 1.5)))
	_receive(CLIENT, _mine(1, 1, Vector3(-0.5, 0.0, 1.5)))
	assert_eq([mines.placed.size(), _refused("mine")], [2, 1])


func test_a_clients_age_of_another_clients_message_counts_the_senders_leg() -> void:
	if _open() == null:
		return
	# This peer is a client now (no ENet here: its own leg to the server reads 0 ms).
	_play.authority = PongNetAuthority.new(CLIENT, PackedInt64Array([HOST, CLIENT]))
	var other: int = 77
	# A pose reports the sender's leg (40 ms): it crossed that leg, then ours.
	assert_almost_eq(_play._age_of(other, _now_s(), 40), 0.040, 0.002, "its pose")
	# Its later messages that carry no leg (a shot, a mine) keep the leg it reported.
	assert_almost_eq(_play._age_of(other, _now_s()), 0.040, 0.002, "its shot")
	# The server's messages cross our leg only, whatever they say.
	assert_almost_eq(_play._age_of(HOST, _now_s(), 40), 0.0, 0.002, "the server's")


func _now_s() -> float:
	return Time.get_ticks_usec() / 1e6
