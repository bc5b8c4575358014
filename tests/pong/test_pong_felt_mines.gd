extends "res://tests/pong/pong_felt_suite.gd"
## Each kind of mine reaches the hand as designed: slow, heavy, remote and the one that
## only rumbles. See pong_felt_suite.gd for how the actions are performed and the forces
## read.


func test_a_slow_mine_resists_the_hands_motion() -> void:
	var from: int = _step_on_mine("slow")
	if from < 0:
		return
	# The hand swings left and right (the mouse), 1 Hz, half the workspace.
	var swing: Callable = func() -> bool:
		var t: float = (_probe.mark() - from) * PongServo.TICK_S
		_move_hand(Vector2(0.5 * sin(TAU * t), 0.0))
		return false
	_probe.run(3.0, swing)
	assert_not_null(_servo_effect("slow"), "the servo runs the slow effect")
	var damping: float = _match.court.settings.slow_damping_n_s_per_m
	var ratios: Array[float] = []
	var alignment: float = 0.0
	for i: int in range(from + 500, from + 3000):
		var velocity: Vector3 = _device_velocity(i)
		if velocity.length() < 0.1:
			continue
		var force: Vector3 = _probe.force(i)
		ratios.append(force.length() / velocity.length())
		alignment += force.normalized().dot(-velocity.normalized())
	if not assert_gt(ratios.size(), 500, "the hand moved faster than 0.1 m/s"):
		return
	ratios.sort()
	var median: float = ratios[floori(ratios.size() * 0.5)]
	print("    slow: |F|/|v| median %.2f N s/m (configured %.2f)" % [median, damping])
	assert_almost_eq(median, damping, damping * 0.3, "F = -b v: the configured damping")
	assert_gt(alignment / ratios.size(), 0.9, "against the hand's motion")


func test_a_heavy_mine_weighs_the_hand_down_for_its_duration() -> void:
	var from: int = _step_on_mine("heavy")
	if from < 0:
		return
	var duration: float = _match.court.settings.mine_effect_duration_s
	var ramp: float = _match.court.settings.mine_effect_ramp_s
	var weight: float = _match.court.settings.heavy_force_n
	_probe.run(duration + 0.5)
	var middle: int = from + roundi(duration * 0.5 / PongServo.TICK_S)
	var held: Vector3 = _probe.mean(middle - 50, middle + 50)
	assert_almost_eq(held.y, -weight, weight * EFFECT_FORCE_TOLERANCE, "the weight, newtons down")
	assert_lt(Vector2(held.x, held.z).length(), QUIET_N, "straight down")
	# The end: the force falls through half its size half a ramp before the duration.
	var last: int = from
	for i: int in range(middle, _probe.mark()):
		if -_probe.force(i).y >= weight * 0.5:
			last = i
	var end_s: float = (last + 1 - from) * PongServo.TICK_S
	assert_almost_eq(end_s, duration - ramp * 0.5, EFFECT_END_TOLERANCE_S, "it lasts its duration")
	assert_lt(_probe.force(_probe.mark() - 1).length(), QUIET_N, "then nothing")


func test_a_remote_mine_pulls_the_hand_to_the_owners_mirrored_stylus() -> void:
	_hand_on_mine = Vector2(0.8, 0.0)
	var from: int = _step_on_mine("remote")
	if from < 0:
		return
	_probe.run(2.0)
	var at: int = _probe.mark() - 1
	var state: PongState = _probe.states[at]
	var scale: float = _match.court.workspace_scale
	var self_m: Vector3 = (state.paddle_centers[0] - _match.avatar_of(0)) / scale
	var owner_m: Vector3 = (
		PongCourt.side_rotation(1).inverse() * _match.controllers[1].intent.paddle_offset / scale
	)
	var target: Vector3 = Vector3(-owner_m.x, owner_m.y, owner_m.z)
	var cap: float = _match.court.settings.remote_max_force_n
	var force: Vector3 = _probe.force(at)
	assert_almost_eq(force.length(), cap, cap * EFFECT_FORCE_TOLERANCE, "the spring at its cap")
	assert_gt(
		force.normalized().dot((target - self_m).normalized()),
		0.95,
		"toward the owner's stylus mirrored left-right"
	)


func test_a_none_mine_only_rumbles() -> void:
	var from: int = _step_on_mine("none")
	if from < 0:
		return
	_probe.run(2.5)
	var rumble: float = _probe.peak(from, from + 100)
	assert_almost_eq(
		rumble, PongHandFeedback.MINE_RUMBLE_N, PongHandFeedback.MINE_RUMBLE_N * 0.2, "a rumble"
	)
	var at: Vector3 = _probe.force(_probe.peak_index(from, from + 100))
	assert_gt(absf(at.normalized().y), 0.9, "along the device's vertical")
	# A decaying buzz: down to 1/e after its decay time, gone within 2.5 s.
	var decay: int = roundi(PongHandFeedback.MINE_RUMBLE_DECAY_S / PongServo.TICK_S)
	var later: float = _probe.peak(from + decay - 20, from + decay + 20)
	assert_almost_eq(later, rumble / exp(1.0), rumble * 0.1, "1/e after its decay time")
	assert_lt(_probe.peak(from + 2400), 0.005, "gone within 2.5 s")
	assert_true(_match.snapshot.effects.is_empty(), "no effect after it")
