extends TestSuite
## The start card's gauge draws the start zone as it is tested: the handle's dot lies
## inside the drawn ring exactly when the trial's start counts it inside, at the
## configured tolerance and at others.

const TOLERANCES: Array[float] = [0.05, 0.01, 0.2]

var _gauge: CentreGauge = null


func before_each() -> void:
	_gauge = CentreGauge.new()
	_gauge.size = Vector2(110.0, 110.0)
	add_child_autofree(_gauge)
	_gauge.target = Vector2(0.3, -0.2)


func _dot_in_ring() -> bool:
	return _gauge.dot_position().distance_to(_gauge.size * 0.5) <= _gauge.zone_radius()


func test_the_dot_is_in_the_ring_exactly_when_the_start_counts_it_in() -> void:
	for tolerance: float in TOLERANCES:
		_gauge.tolerance = tolerance
		for fraction: float in [0.0, 0.5, 0.95, 1.05, 2.0, 10.0]:
			for angle: float in [0.0, 1.0, 2.5, 4.0]:
				_gauge.hand = _gauge.target + Vector2.from_angle(angle) * tolerance * fraction
				assert_eq(
					_dot_in_ring(),
					_gauge.is_inside(),
					"tolerance %s, %s of it at angle %s" % [tolerance, fraction, angle]
				)


func test_the_zone_is_wide_enough_to_see_and_the_dot_smaller_than_it() -> void:
	for tolerance: float in TOLERANCES:
		_gauge.tolerance = tolerance
		assert_gt(_gauge.zone_radius(), 4.0 * CentreGauge.DOT_RADIUS, "at %s" % tolerance)


func test_a_handle_far_away_sits_on_the_edge_in_its_direction() -> void:
	_gauge.hand = _gauge.target + Vector2(0.8, 0.0)
	var dot: Vector2 = _gauge.dot_position() - _gauge.size * 0.5
	assert_almost_eq(dot.normalized(), Vector2.RIGHT, 1e-4)
	assert_almost_eq(dot.length(), 110.0 * 0.5 - 6.0, 1e-3, "on the disc's edge")
