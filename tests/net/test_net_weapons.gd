extends "res://tests/net/net_play_suite.gd"
## Bullets and mines in a networked match, without sockets: the message checks, and the
## authority rules of [PongNetWeapons] on one peer of a real stepped match (the host, seat
## 0; the client, peer 42, drives seat 1). Received messages are handed to the handlers
## with their sender's id; what this peer sends is recorded.

const PongTestCourt := preload("res://tests/pong/pong_test_court.gd")


func _open() -> PongNetWeapons:
	var play: RecordingPlay = _open_play()
	return play.weapons if play != null else null


# --- the protocol's checks ---


func test_good_weapon_messages_pass_the_protocol_checks() -> void:
	var court: PongCourt = PongTestCourt.make()
	var up: Vector3 = Vector3.UP
	assert_eq(PongNetProtocol.check_bullet(1, 2, 0, Vector3(0, 1, -2), up, 3.0, court), "")
	assert_eq(PongNetProtocol.check_mine(1, 2, 2, Vector3(0.5, 0, 1.5), "remote", court), "")
	assert_eq(PongNetProtocol.check_weapon_hurt(0, 2, "bullet", 1, 7), "")


func test_bad_weapon_messages_are_refused_with_the_reason() -> void:
	var court: PongCourt = PongTestCourt.make()
	var at: Vector3 = Vector3(0, 1, -2)
	var up: Vector3 = Vector3.UP
	var bullet: Callable = PongNetProtocol.check_bullet
	assert_true(str(bullet.call("1", 2, 0, at, up, 3.0, court)).contains("seat is a String"))
	assert_true(str(bullet.call(2, 2, 0, at, up, 3.0, court)).contains("seat 2 is out of"))
	assert_true(str(bullet.call(1, 2, -1, at, up, 3.0, court)).contains("bullet id -1"))
	assert_true(str(bullet.call(1, 2, 0, Vector3(0, 1, 99), up, 3.0, court)).contains("origin"))
	assert_true(str(bullet.call(1, 2, 0, at, up * 2.0, 3.0, court)).contains("direction"))
	assert_true(
		str(bullet.call(1, 2, 0, at, Vector3(NAN, 0, 0), 3.0, court)).contains("not finite")
	)
	assert_true(str(bullet.call(1, 2, 0, at, up, "now", court)).contains("time is a String"))
	var mine: Callable = PongNetProtocol.check_mine
	var spot: Vector3 = Vector3(0.5, 0, 1.5)
	assert_true(str(mine.call(1, 2, 4, spot, "none", court)).contains("mine id 4 is out of"))
	assert_true(str(mine.call(1, 2, 0, spot, "remote", court)).contains("is not mine 0's, slow"))
	assert_true(str(mine.call(1, 2, 0, spot, 7, court)).contains("kind 7"))
	assert_true(str(mine.call(1, 2, 0, spot + Vector3.UP, "slow", court)).contains("mine position"))
	assert_true(str(mine.call(1, 2, 0, Vector3(0, 0, 9), "slow", court)).contains("mine position"))
	assert_true(str(mine.call(0, 2, 0, spot, "slow", court)).contains("its owner's own territory"))
	var hurt: Callable = PongNetProtocol.check_weapon_hurt
	assert_true(str(hurt.call(0, 2, "floor", 1, 0)).contains("cause floor is not a weapon"))
	var long: String = str(hurt.call(0, 2, "x".repeat(65536), 1, 0))
	assert_true(long.contains("is not a weapon") and long.length() < 100, long.left(100))
	assert_true(str(hurt.call(1, 2, "mine", 1, 0)).contains("never hurts its owner"))
	assert_true(str(hurt.call(0, 2, "mine", 1, 1 << 31)).contains("weapon id"))


# --- the authority rules on one peer ---


func test_a_shot_is_taken_once_from_its_seats_peer_and_keeps_the_cooldown() -> void:
	var weapons: PongNetWeapons = _open()
	if weapons == null:
		return
	var bullets: PongBullets = _play.match_node.bullets
	var origin: Vector3 = Vector3(0.0, 1.0, -2.0)
	weapons.on_bullet(HOST, 1, 0, origin, Vector3.BACK, 10.0)
	assert_eq(bullets.flying.size(), 0, "not from the host: seat 1 is the client's")
	weapons.on_bullet(CLIENT, 1, 0, origin, Vector3.BACK, 10.0)
	assert_eq(bullets.flying.size(), 1, "from the seat's peer: it flies")
	var flying: PongBullets.Bullet = bullets.flying[0]
	assert_eq([flying.owner, flying.id], [1, 0])
	# It flew on for the message's age (no round trip measured here: at least 0).
	assert_true(flying.position.z >= origin.z and flying.position.z - origin.z < 3.6)
	weapons.on_bullet(CLIENT, 1, 0, origin, Vector3.BACK, 11.0)
	weapons.on_bullet(CLIENT, 1, 1, origin, Vector3.BACK, 10.1)
	assert_eq(bullets.flying.size(), 1, "a reused number and a shot within the cooldown are not")
	weapons.on_bullet(CLIENT, 1, 1, origin, Vector3.BACK, 10.5)
	assert_eq(bullets.flying.size(), 2, "the next shot after the cooldown is")
	assert_eq(_play.report.refused.get("bullet", 0), 3)
	assert_eq(weapons.shots, [[1, 0], [1, 1]])


func test_a_mine_is_put_where_its_owner_put_it_once_and_only_from_its_peer() -> void:
	var weapons: PongNetWeapons = _open()
	if weapons == null:
		return
	var mines: PongMines = _play.match_node.mines
	var spot: Vector3 = Vector3(0.3, 0.0, 1.5)
	weapons.on_mine(HOST, 1, 0, spot, "slow")
	assert_eq(mines.placed.size(), 0, "not from the host")
	weapons.on_mine(CLIENT, 1, 2, spot, "remote")
	assert_eq(mines.placed.size(), 1, "the client's third mine, where it put it")
	assert_eq(mines.placed[0].position, spot)
	assert_eq(mines.next_kind(1), "none", "its earlier numbers are spent")
	weapons.on_mine(CLIENT, 1, 1, spot + Vector3.RIGHT, "heavy")
	weapons.on_mine(CLIENT, 1, 2, spot + Vector3.RIGHT, "remote")
	assert_eq(mines.placed.size(), 1, "numbers are not reused")
	assert_eq(_play.report.refused.get("mine", 0), 3)


func test_a_weapon_hurt_counts_once_only_from_the_victims_peer_for_a_known_weapon() -> void:
	var weapons: PongNetWeapons = _open()
	if weapons == null:
		return
	var rules: PongRules = _play.match_node.rules
	var mines: PongMines = _play.match_node.mines
	# The host's own mine (placed here) in the client's half.
	var mine: PongMines.Mine = mines.place(0, Vector3(0.3, 1.0, 1.5), _play.match_node.court)
	_play.match_node.mine_placed.emit(mine)
	assert_eq(_play.sent_of(&"_mine").size(), 1, "the host's mine went out")
	weapons.on_hurt(HOST, 1, "mine", 0, mine.id)
	assert_eq(rules.get_health(1), 99, "the host does not judge the client's seat")
	weapons.on_hurt(CLIENT, 1, "mine", 0, mine.id + 1)
	assert_eq(rules.get_health(1), 99, "an unknown mine")
	weapons.on_hurt(CLIENT, 1, "mine", 0, mine.id)
	var lost: int = PongRules.DAMAGE[PongRules.CAUSE_MINE]
	assert_eq(rules.get_health(1), 99 - lost, "the client's word on its seat")
	assert_eq(mines.placed.size(), 0, "the mine went off here too")
	weapons.on_hurt(CLIENT, 1, "mine", 0, mine.id)
	assert_eq(rules.get_health(1), 99 - lost, "a mine hurts once")
	assert_eq(_play.report.refused.get("weapon hurt", 0), 3)
	assert_eq(weapons.hurts, [[1, "mine", 0, mine.id]])


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
	weapons.on_bullet(CLIENT, 1, 0, from, Vector3.BACK, 10.0)
	# The host's bullet through the client's avatar: not judged here (no hurt).
	var client_avatar: Vector3 = match_node.avatar_of(1)
	var bullet: PongBullets.Bullet = match_node.bullets.fire(
		0, client_avatar + Vector3(0.0, 0.0, 0.5), Vector3.FORWARD
	)
	match_node.bullet_fired.emit(bullet)
	match_node.run_until(func() -> bool: return match_node.bullets.flying.is_empty(), 1.0)
	var hurts: Array[Array] = _play.sent_of(&"_weapon_hurt")
	assert_eq(hurts, [[&"_weapon_hurt", 0, "bullet", 1, 0]], "only the hit on seat 0")
	var lost: int = PongRules.DAMAGE[PongRules.CAUSE_BULLET]
	assert_eq(match_node.rules.get_health(0), 99 - lost)
	assert_eq(match_node.rules.get_health(1), 99, "seat 1's peer decides its own")
	assert_eq(
		_play.sent_of(&"_bullet").size(), 1, "the host's shot went out, the client's not back"
	)


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
