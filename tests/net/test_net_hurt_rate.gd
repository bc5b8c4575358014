extends TestSuite
## The server's bound on floor points: a victim loses no more of them than a ball can bounce,
## counted by the bounces' own times whatever the order their claims come in.

const PongTestCourt := preload("res://tests/pong/pong_test_court.gd")
## A point of the test court's territory 0.
const NEAR: Vector3 = Vector3(0.3, 0.07, 1.5)
const ACCEPT: int = PongNetHurtJudge.Verdict.ACCEPT


func test_a_victim_loses_no_more_floor_points_than_a_ball_can_bounce() -> void:
	var judge: PongNetHurtJudge = _judge()
	assert_almost_eq(judge.rate_per_s, 6.0 / 1.6, 1e-9, "g / (2 x 0.8 m/s)")
	# Bounces recorded 0.2 s apart (faster than a ball bounces), each claimed at once.
	var accepted: int = 0
	for i: int in 10:
		judge.observe_floor(1.0 + i * 0.2, NEAR)
		var verdict: Array = judge.judge(1.0 + i * 0.2, 1.0 + i * 0.2, 0, 0)
		accepted += 1 if verdict[0] == ACCEPT else 0
	# A burst of 2, then 3.75 a second over 1.8 s: at most 2 + 6.75.
	assert_true(accepted >= 8 and accepted <= 9, "accepted %d of 10" % accepted)


func test_the_bound_holds_when_the_bounces_are_recorded_latest_first() -> void:
	var judge: PongNetHurtJudge = _judge()
	var accepted: int = 0
	for i: int in 10:
		judge.observe_floor(2.8 - i * 0.2, NEAR)
		accepted += 1 if judge.judge(3.0, 3.0, 0, 0)[0] == ACCEPT else 0
	assert_true(accepted >= 8 and accepted <= 9, "accepted %d of 10" % accepted)


func test_claims_that_come_before_an_earlier_bounces_claim_are_honest() -> void:
	# A hiccup: three bounces 0.3 s apart (as a ball bounces), the newest recorded first (our
	# copy saw it) and the earlier ones as the master's late states show them; each claimed.
	var judge: PongNetHurtJudge = _judge()
	for t: float in [1.6, 1.3, 1.0]:
		judge.observe_floor(t, NEAR)
		var verdict: Array = judge.judge(2.0, 2.0, 0, 0)
		assert_eq(verdict[0], ACCEPT, "the bounce at %.1f s: %s" % [t, verdict[1]])


func _judge() -> PongNetHurtJudge:
	return PongNetHurtJudge.new(PongTestCourt.make(), 2)
