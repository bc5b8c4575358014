extends TestSuite
## The computer player's ball prediction against closed forms: a free parabola, a floor
## bounce with the court's restitution, a side-wall reflection, a ball that ends rolling.

const PongTestCourt := preload("res://tests/pong/pong_test_court.gd")
const G: float = 6.0

var _court: PongCourt = null
var _predictor: PongPredictor = null


func before_each() -> void:
	_court = PongTestCourt.make()
	_predictor = PongPredictor.new(_court)


func test_a_free_flight_is_the_closed_form_parabola() -> void:
	var p0: Vector3 = Vector3(0.2, 1.5, 0.0)
	var v0: Vector3 = Vector3(0.5, 1.0, 2.0)
	var path: Array[PongPredictor.Segment] = _predictor.path(p0, v0, G, 0.5)
	assert_eq(path.size(), 1, "no bounce within 0.5 s")
	for i: int in 11:
		var t: float = 0.05 * i
		var expected: Vector3 = Vector3(0.2 + 0.5 * t, 1.5 + t - 3.0 * t * t, 2.0 * t)
		assert_almost_eq(PongPredictor.position_at(path, t), expected, 1e-5, "t = %.2f" % t)
		assert_almost_eq(PongPredictor.velocity_at(path, t), Vector3(0.5, 1.0 - G * t, 2.0), 1e-5)


func test_a_dropped_ball_bounces_with_the_courts_restitution() -> void:
	var r: float = _court.ball_radius
	var path: Array[PongPredictor.Segment] = _predictor.path(Vector3(0, 1, 1), Vector3.ZERO, G, 2.0)
	var t_floor: float = sqrt(2.0 * (1.0 - r) / G)
	assert_gt(path.size(), 1)
	assert_eq(path[0].ends_with, "floor")
	assert_almost_eq(path[1].start, t_floor, 1e-4, "the floor is met at the closed-form time")
	var up: float = G * t_floor * _court.restitution_court
	var t: float = t_floor + 0.1
	var expected: Vector3 = Vector3(0, r + up * 0.1 - 0.5 * G * 0.01, 1)
	assert_almost_eq(PongPredictor.position_at(path, t), expected, 1e-4, "second arc")
	assert_almost_eq(PongPredictor.first_floor_time_in(path, 0), t_floor, 1e-4, "territory 0")
	assert_eq(PongPredictor.first_floor_time_in(path, 1), -1.0, "never in territory 1")


func test_a_side_wall_reflects_the_ball_across() -> void:
	var r: float = _court.ball_radius
	var path: Array[PongPredictor.Segment] = _predictor.path(
		Vector3(0, 0.9, -1), Vector3(3, 0, 0), 0.0, 1.0
	)
	var t_wall: float = (_court.half_width - r) / 3.0
	assert_almost_eq(path[1].start, t_wall, 1e-5)
	assert_eq(path[0].ends_with, "wall")
	assert_almost_eq(path[1].velocity, Vector3(-3.0 * _court.restitution_wall, 0, 0), 1e-5)
	var after: Vector3 = PongPredictor.position_at(path, t_wall + 0.2)
	assert_almost_eq(after.x, _court.half_width - r - 0.2 * 3.0 * _court.restitution_wall, 1e-5)


func test_slow_bounces_end_in_rolling_without_gravity() -> void:
	var path: Array[PongPredictor.Segment] = _predictor.path(
		Vector3(0, 0.3, 0.5), Vector3(0, 0, 0.1), G, 10.0
	)
	var last: PongPredictor.Segment = path[path.size() - 1]
	assert_eq(last.gravity, 0.0, "the last segment rolls")
	assert_eq(last.velocity.y, 0.0)
	assert_almost_eq(PongPredictor.position_at(path, last.start + 0.5).y, _court.ball_radius, 1e-4)


func test_the_parabola_closed_form_itself() -> void:
	assert_almost_eq(
		PongPredictor.parabola_at(Vector3(1, 2, 3), Vector3(1, 0, -1), 10.0, 0.2),
		Vector3(1.2, 1.8, 2.8),
		1e-6
	)
