extends "res://tests/pong/pong_felt_suite.gd"
## The forces of the gun and the paddle reach the hand: firing, a bullet's hit, a paddle hit
## without and with spin (and the spin's grip on the next paddle it meets). See
## pong_felt_suite.gd for how the actions are performed and the forces read.


func test_firing_kicks_the_hand_back_along_the_gun() -> void:
	if not _open(PongMatch.Mode.VS_COMPUTER):
		return
	# Past the servo's start ramp (a force builds up over its first 0.3 s).
	_press(0, &"gun_toggle")
	_probe.run(0.5)
	assert_lt(_probe.peak(0), QUIET_N, "nothing on the hand before firing")
	var fired: Array[PongBullets.Bullet] = []
	_match.bullet_fired.connect(fired.append)
	var from: int = _probe.mark()
	_press(0, &"fire")
	_probe.run(0.3)
	if not assert_eq(fired.size(), 1, "the fire key fired one bullet"):
		return
	var away: Vector3 = _device(0, -fired[0].velocity)
	_assert_pulse(from, "recoil", away)


func test_a_bullet_hit_pushes_the_hand_along_the_bullet() -> void:
	if not _open(PongMatch.Mode.TWO_PLAYERS):
		return
	# The keyboard player aims level at the device player's body, across the court.
	var shooter: PongHumanPlayer = _match.controllers[1] as PongHumanPlayer
	shooter.tilt = -0.1
	shooter.yaw = 0.0
	var hits: Array[Dictionary] = []
	var hit_at: Array[int] = []
	_match.bullet_hit.connect(
		func(shot: Dictionary) -> void:
			hits.append(shot)
			hit_at.append(_probe.mark())
	)
	_press(1, &"p1_gun_toggle")
	_probe.run(0.05)
	_press(1, &"p1_fire")
	var hit: bool = _probe.run(1.5, func() -> bool: return not hits.is_empty())
	if not assert_true(hit, "the bullet reached the device player"):
		return
	var victim: int = hits[0]["victim"]
	assert_eq(victim, 0, "it hit player 0")
	_probe.run(0.3)
	var direction: Vector3 = hits[0]["direction"]
	# The hit's order goes out in the update that found it: the ticks before the next
	# update are the first that can render it.
	_assert_pulse(hit_at[0], "hit", _device(0, direction))
	assert_eq(_match.rules.get_health(0), _match.rules.start_health - 3, "a bullet costs 3")


func test_a_paddle_hit_pushes_the_hand_along_the_paddles_normal() -> void:
	if not _open(PongMatch.Mode.VS_COMPUTER):
		return
	var contact: Dictionary = _meet_serve(false)
	if contact.is_empty():
		return
	var from: int = contact["from"]
	var to: int = contact["to"]
	var facing: Vector3 = contact["facing"]
	var peak: int = _probe.peak_index(from, to)
	var force: Vector3 = _probe.force(peak)
	var limit: float = _match.court.settings.contact_force_n
	assert_gt(force.length(), 0.2, "the contact is felt")
	assert_lt(force.length(), limit + 0.05, "no more than the contact law's c")
	assert_gt(force.normalized().dot(-facing), 0.97, "pushed back, along the paddle's normal")
	var across: Vector3 = force - facing * force.dot(facing)
	assert_lt(across.length(), 0.05, "nothing across the paddle without spin")
	var contact_s: float = (to - from) * PongServo.TICK_S
	assert_almost_eq(
		_probe.span_s(from - 5, 0.05, to + 20), contact_s, 0.012, "for as long as they touch"
	)


func test_a_spin_hit_spins_the_ball_drags_the_hand_and_the_spin_bends_the_next_hit() -> void:
	if not _open(PongMatch.Mode.VS_COMPUTER):
		return
	_press(0, &"spin_toggle")
	var contact: Dictionary = _meet_serve(true)
	if contact.is_empty():
		return
	var to: int = contact["to"]
	var facing: Vector3 = contact["facing"]
	var spun: PongState = _probe.states[to]
	assert_gt(spun.ball_spin.length(), 5.0, "the brush spun the ball (rad/s)")
	# The spinning ball drags the hand along its surface, in the paddle's plane.
	var gain: float = _match.court.settings.spin_force_gain
	var facing_world: Vector3 = contact["facing_world"]
	var lever: Vector3 = -facing_world * _match.court.ball_radius
	var expected: Vector3 = _device(0, spun.ball_spin.cross(lever) * gain)
	var felt: Vector3 = _probe.force(to - 1)
	var across: Vector3 = felt - facing * felt.dot(facing)
	print(
		(
			"    spin drag: %.3f N felt across the paddle, %.3f N expected"
			% [across.length(), expected.length()]
		)
	)
	assert_almost_eq(across.length(), expected.length(), expected.length() * 0.4 + 0.02, "size")
	assert_gt(across.normalized().dot(expected.normalized()), 0.8, "along the ball's surface")
	# The next contact with a spin the ball brings (served back with this spin, the spin
	# paddle off, no brush): it grips the paddle's face and bends the ball.
	_press(0, &"spin_toggle")
	_events.clear()
	var next: Dictionary = _meet_serve(false, spun.ball_spin)
	if next.is_empty():
		return
	_assert_bent_by_spin(_contact_ticks(0), 0)


func test_the_door_refuses_an_effect_the_servo_would_refuse() -> void:
	if not _open(PongMatch.Mode.VS_COMPUTER):
		return
	var refused: Array[Dictionary] = [
		{"args": [0, "bogus", 1.0, 0.1], "says": "unknown kind 'bogus'"},
		{"args": [4, "heavy", 1.0, 0.1], "says": "player must be 0..1"},
		{"args": [0, "hit", 1.0, 0.1], "says": "a hit needs a direction"},
		{"args": [0, "recoil", 1.0, 0.1, Vector3(NAN, 0.0, 0.0)], "says": "needs a direction"},
		{"args": [0, "remote", 1.0, 0.1, Vector3.ZERO, 0], "says": "another player than 0"},
		{"args": [0, "remote", 1.0, 0.1, Vector3.ZERO, 7], "says": "owner must be 0..1"},
		{"args": [0, "heavy", -2.0, 0.1], "says": "magnitude_n must be"},
		{"args": [0, "heavy", INF, 0.1], "says": "magnitude_n must be"},
		{"args": [0, "heavy", 1.0, 0.0], "says": "duration_s must be"},
	]
	for case: Dictionary in refused:
		var says: String = case["says"]
		expect_error(says)
		var args: Array = case["args"]
		var accepted: bool = PongServo.shared().callv(&"apply_effect", args)
		assert_false(accepted, "refused: %s" % says)
	_probe.run(0.05)
	assert_true(_match.snapshot.effects.is_empty(), "nothing reached the servo")
	assert_lt(_probe.peak(0), QUIET_N, "nothing reached the hand")
	# The defaults are valid: the owner is the player across, the strength the servo's own.
	var sent: bool = PongServo.shared().apply_effect(
		0, "slow", PongServo.DEFAULT_STRENGTH, 0.5, Vector3.ZERO
	)
	assert_true(sent, "a slow effect with the defaults is sent")
	_probe.run(0.05)
	assert_not_null(PongServo.effect_in(_match.snapshot, "slow"), "and runs in the servo")
