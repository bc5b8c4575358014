extends TestSuite
## The computer player's decisions without the servo: where it meets an incoming lob
## (on the closed-form parabola, in its half, before the bounce), the swing that sends the
## ball where it wants (the mirror law), beginner shots at the target, its reaction delay
## and its avatar's speed limit.

const PongTestCourt := preload("res://tests/pong/pong_test_court.gd")
const REACH: float = 0.5
const G: float = 6.0

var _court: PongCourt = null


func before_each() -> void:
	_court = PongTestCourt.make()


func test_it_meets_an_incoming_lob_on_its_parabola_before_the_bounce() -> void:
	var ai: PongAi = _exact_ai(1)
	var p0: Vector3 = Vector3(0.3, 1.2, 0.5)
	var v0: Vector3 = Vector3(-0.2, 2.5, -3.0)
	var plan: PongAi.Contact = ai.plan_contact(p0, v0, 0.0, ai.home())
	if not assert_not_null(plan, "a plan"):
		return
	var t: float = plan.time
	var point: Vector3 = plan.point
	assert_almost_eq(point, p0 + v0 * t + Vector3(0, -0.5 * G * t * t, 0), 1e-4, "on the arc")
	assert_eq(PongCourt.territory_of(point), 1, "in its own half")
	var bounce_t: float = _time_to_floor(p0, v0)
	assert_lt(t, bounce_t, "before the ball would bounce in its half")
	assert_lt(absf(point.y - _court.beginner_height), REACH, "within the paddle's reach")
	var stand: Vector3 = plan.avatar
	assert_lt(stand.distance_to(point), REACH, "the avatar stands within reach of it")
	assert_eq(PongCourt.territory_of(stand), 1)


func test_the_swing_sends_the_ball_where_it_aims_by_the_mirror_law() -> void:
	var ai: PongAi = _exact_ai(1)
	var plan: PongAi.Contact = ai.plan_contact(
		Vector3(0, 1.2, 0.5), Vector3(0, 2.5, -3), 0.0, ai.home()
	)
	if not assert_not_null(plan, "a plan"):
		return
	var n: Vector3 = plan.normal
	var u: float = plan.speed
	var v_in: Vector3 = plan.velocity_in
	var e: float = _court.restitution_paddle
	var v_out: Vector3 = v_in - (1.0 + e) * (v_in - n * u).dot(n) * n
	var wanted: Vector3 = ai.wanted_velocity(plan.point)
	assert_almost_eq(v_out, wanted, 1e-4, "a paddle moving at u n sends v_in off as wanted")
	var landing_t: float = _time_to_floor(plan.point, wanted)
	var landing: Vector3 = PongPredictor.parabola_at(plan.point, wanted, G, landing_t)
	assert_eq(PongCourt.territory_of(landing), 0, "it lands in the opponent's half")
	assert_lt(absf(landing.x), _court.half_width, "between the side walls")
	assert_lt(absf(landing.z), _court.half_length, "before the back wall")


func test_in_beginner_mode_it_shoots_flat_at_the_opponents_target() -> void:
	var ai: PongAi = _exact_ai(0)
	ai.beginner = true
	var from: Vector3 = Vector3(0.6, _court.beginner_height, 1.5)
	var wanted: Vector3 = ai.wanted_velocity(from)
	assert_eq(wanted.y, 0.0, "in the plane")
	var t: float = (-_court.half_length - from.z) / wanted.z
	var at_wall: Vector3 = from + wanted * t
	assert_true(_court.in_target(at_wall), "it reaches the far wall within the target")


func test_a_ball_going_away_gives_no_plan() -> void:
	var ai: PongAi = _exact_ai(1)
	assert_null(ai.plan_contact(Vector3(0, 1, -1), Vector3(0, 1, 3), 0.0, ai.home()))


func test_it_acts_only_after_its_reaction_delay() -> void:
	var ai: PongAi = _exact_ai(1)
	ai.reaction_delay_s = 0.2
	var dt: float = 0.01
	var now: float = 0.0
	# The ball rests in the far court for a while, then is sent toward the computer.
	for i: int in 50:
		ai.decide(now, dt, Vector3(0, 0.07, 2), Vector3.ZERO, Vector3(0, 0.9, 2))
		now += dt
	var sent_at: float = now
	var first_plan: float = -1.0
	var p: Vector3 = Vector3(0, 1.2, 0.5)
	var v: Vector3 = Vector3(0, 2.5, -3)
	while now < sent_at + 0.6:
		var t: float = now - sent_at
		var ball: Vector3 = p + v * t + Vector3(0, -0.5 * G * t * t, 0)
		ai.decide(now, dt, ball, v + Vector3(0, -G * t, 0), Vector3(0, 0.9, 2))
		if first_plan < 0.0 and ai.get_plan() != null:
			first_plan = now - sent_at
		now += dt
	assert_gt(first_plan, 0.0, "it plans")
	assert_gt(first_plan, 0.2 - 1e-6, "not before its reaction delay")
	assert_lt(first_plan, 0.35, "soon after it")


func test_its_avatar_never_outruns_its_top_speed() -> void:
	var ai: PongAi = _exact_ai(1)
	var dt: float = 0.02
	var now: float = 0.0
	var before: Vector3 = ai.intent.avatar
	var fastest: float = 0.0
	for i: int in 100:
		var t: float = i * dt
		var ball: Vector3 = Vector3(1.0, 1.2, 0.2) + Vector3(0.0, 2.0, -3.0) * t
		ball.y -= 0.5 * G * t * t
		ai.decide(now, dt, ball, Vector3(0, 2.0 - G * t, -3.0), Vector3(0, 0.9, 2))
		fastest = maxf(fastest, ai.intent.avatar.distance_to(before) / dt)
		before = ai.intent.avatar
		now += dt
	assert_gt(fastest, 0.5, "it moved")
	assert_lt(fastest, ai.max_avatar_speed + 1e-3)
	assert_eq(PongCourt.territory_of(ai.intent.avatar), 1, "it stays in its half")


func _exact_ai(player: int) -> PongAi:
	var ai: PongAi = PongAi.new(player, _court, REACH, 7)
	ai.reaction_delay_s = 0.0
	ai.hit_error_m = 0.0
	ai.aim_error_m = 0.0
	ai.use_weapons = false
	return ai


func _time_to_floor(p: Vector3, v: Vector3) -> float:
	var h: float = p.y - _court.ball_radius
	return (v.y + sqrt(v.y * v.y + 2.0 * G * h)) / G
