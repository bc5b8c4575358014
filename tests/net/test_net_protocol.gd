extends TestSuite
## The checks every received message passes: types, finiteness, ranges, sizes.

const PongTestCourt := preload("res://tests/pong/pong_test_court.gd")

var _court: PongCourt = null


func before_each() -> void:
	_court = PongTestCourt.make()


func _ball(overrides: Dictionary) -> String:
	var m: Dictionary = {
		"epoch": 1,
		"seq": 2,
		"time": 3.5,
		"position": Vector3(0, 1, -1),
		"velocity": Vector3(0, 0, 5),
		"spin": Vector3.ZERO,
	}
	m.merge(overrides, true)
	return PongNetProtocol.check_ball(
		m["epoch"], m["seq"], m["time"], m["position"], m["velocity"], m["spin"], _court, 120.0
	)


func test_a_good_ball_state_passes() -> void:
	assert_eq(_ball({}), "")


func test_bad_ball_states_are_refused_with_the_reason() -> void:
	assert_true(_ball({"epoch": "1"}).contains("epoch is a String"), _ball({"epoch": "1"}))
	assert_true(_ball({"seq": -1}).contains("seq -1 is out of"))
	assert_true(_ball({"time": NAN}).contains("time"))
	assert_true(_ball({"position": Vector3(0, 1, 99)}).contains("position"))
	assert_true(_ball({"position": [0, 1, 2]}).contains("not a Vector3"))
	assert_true(_ball({"velocity": Vector3(INF, 0, 0)}).contains("not finite"))
	var fast: float = _court.max_ball_speed * PongNetProtocol.SPEED_MARGIN + 0.1
	assert_true(_ball({"velocity": Vector3(0, 0, fast)}).contains("velocity"))
	assert_true(_ball({"spin": Vector3(500, 0, 0)}).contains("spin"))


func test_poses_are_checked_for_seat_ranges_and_a_unit_normal() -> void:
	var good: String = PongNetProtocol.check_pose(
		1, 2, Vector3(0, 0.9, -1.8), Vector3(0.1, 0, 0), Vector3.ZERO, Vector3.BACK, _court, 0.5
	)
	assert_eq(good, "")
	var seat: String = PongNetProtocol.check_pose(
		2, 2, Vector3.ZERO, Vector3.ZERO, Vector3.ZERO, Vector3.BACK, _court, 0.5
	)
	assert_true(seat.contains("seat 2"), seat)
	var normal: String = PongNetProtocol.check_pose(
		0, 2, Vector3.ZERO, Vector3.ZERO, Vector3.ZERO, Vector3(0, 0, 0.5), _court, 0.5
	)
	assert_true(normal.contains("unit"), normal)
	var reach: String = PongNetProtocol.check_pose(
		0, 2, Vector3.ZERO, Vector3(0, 0, 3), Vector3.ZERO, Vector3.BACK, _court, 0.5
	)
	assert_true(reach.contains("paddle offset"), reach)


func test_names_must_be_short_non_empty_strings() -> void:
	assert_eq(PongNetProtocol.check_name("Ada"), "")
	assert_ne(PongNetProtocol.check_name("   "), "")
	assert_ne(PongNetProtocol.check_name("x".repeat(65536)), "", "an oversized name")
	assert_ne(PongNetProtocol.check_name(42), "")


func test_channels_are_distinct_and_the_stream_has_its_own() -> void:
	var channels: Array[int] = [
		PongNetProtocol.CHANNEL_BALL, PongNetProtocol.CHANNEL_POSE, PongNetProtocol.CHANNEL_RELIABLE
	]
	assert_eq(channels.size(), 3)
	assert_true(channels.all(func(c: int) -> bool: return c > 0), "0 is Godot's default")
	assert_ne(PongNetProtocol.CHANNEL_BALL, PongNetProtocol.CHANNEL_RELIABLE)
	assert_ne(PongNetProtocol.CHANNEL_POSE, PongNetProtocol.CHANNEL_BALL)


func test_the_timeout_cap_falls_between_enets_fourth_and_fifth_retransmission() -> void:
	for path: Vector2 in [Vector2(110.0, 15.0), Vector2(110.0, 40.0), Vector2(340.0, 20.0)]:
		var rto: float = path.x + 4.0 * path.y
		var cap: int = PongNetProtocol.timeout_max_ms(path.x, path.y)
		assert_gt(cap, 15.0 * rto, "after the fourth try's timeout, round trip %s" % path)
		assert_lt(cap, 31.0 * rto, "before the fifth's, round trip %s" % path)
	assert_eq(PongNetProtocol.timeout_max_ms(8.0, 7.0), 900, "a LAN: the floor, under 31 RTOs")
	assert_eq(PongNetProtocol.timeout_max_ms(5000.0, 100.0), PongNetProtocol.TIMEOUT_CEILING_MS)
	assert_eq(PongNetProtocol.timeout_max_ms(-3.0, -1.0), PongNetProtocol.TIMEOUT_MAX_MS)
