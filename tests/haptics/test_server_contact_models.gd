extends TestSuite
## The two contact models (force_model.contact_model) on a door of the test's own, stepped
## manually: the issue's two measurements on a real device, a horizontal push into a wall
## while standing on a floor and an input pointing away from a wall that is still in contact,
## each under the per-contact default and under the paper's normalised sum. Game axes: x right,
## y down; the floor's normal is UP, a wall on the right has LEFT. The simulated hand is a
## relaxed grip, so a force moves it a little: expectations use the input the door reports.

const K := 2.0
const B := 1.0
const TOL := 1e-4
const TICKS_PER_FRAME := 20
const NORMAL := HapticMovementFacts.MovementForce.NORMAL

var door: HapticsTestKit.Door = null


func before_each() -> void:
	door = autofree(HapticsTestKit.manual())
	assert_true(HapticsTestKit.instant(door))
	assert_true(HapticsTestKit.no_dead_zone(door))


func _contacts(normals: Array[Vector2]) -> HapticFrame:
	var contacts: Array[HapticContact] = []
	for normal: Vector2 in normals:
		contacts.append(HapticsTestKit.contact(normal, K, B))
	return HapticsTestKit.frame_of(contacts)


# Moves the simulated hand to [param hand_m] and renders [param frame] until it is there.
func _settle(hand_m: Vector2, frame: HapticFrame, ticks: int = 300) -> void:
	assert_true(HapticsTestKit.set_hand_m(door, hand_m))
	assert_true(HapticsTestKit.run(door, ticks, frame))


func _use(model: HapticMovementFacts.ContactModel, smoothing: bool) -> void:
	var settings: HapticMovementSettings = HapticsMovement.of(door).get_settings()
	settings.force_model.contact_model = model
	settings.smoothing.enabled = smoothing
	assert_true(HapticsMovement.of(door).apply_settings(settings))


func _normal_force() -> Vector2:
	return HapticsTestKit.movement_part(door, NORMAL)


func test_the_default_is_per_contact() -> void:
	var model: int = HapticsMovement.of(door).get_settings().force_model.contact_model
	assert_eq(model, HapticMovementFacts.ContactModel.PER_CONTACT)
	_use(HapticMovementFacts.ContactModel.PAPER_SUM, true)
	model = HapticsMovement.of(door).get_settings().force_model.contact_model
	assert_eq(model, HapticMovementFacts.ContactModel.PAPER_SUM)


func test_floor_and_wall_a_horizontal_push_gets_the_walls_push_back_only() -> void:
	_use(HapticMovementFacts.ContactModel.PER_CONTACT, false)
	_settle(Vector2(0.06, 0.0), _contacts([Vector2.UP, Vector2.LEFT]))
	var i: Vector2 = door.get_input_vector()
	var forces: HapticForces = door.get_forces()
	assert_gt(i.x, 0.3, "the hand pushes right")
	assert_almost_eq(i.y, 0.0, 1e-3, "and not down")
	var expected: Vector2 = Vector2(-K * i.x, 0.0)
	assert_almost_eq(forces.parts[NORMAL], expected, TOL, "exactly the wall's -k p")
	assert_almost_eq(forces.total.y, 0.0, 1e-3, "nothing upward")
	_settle(Vector2(0.06, 0.0), _contacts([Vector2.LEFT]), 5)
	assert_almost_eq(_normal_force(), expected, TOL, "the same as the wall alone")


func test_floor_and_wall_the_paper_sum_pushes_at_45_degrees() -> void:
	_use(HapticMovementFacts.ContactModel.PAPER_SUM, false)
	_settle(Vector2(0.06, 0.0), _contacts([Vector2.UP, Vector2.LEFT]))
	var i: Vector2 = door.get_input_vector()
	var f_n: Vector2 = _normal_force()
	var n: Vector2 = (Vector2.UP + Vector2.LEFT).normalized()
	assert_almost_eq(f_n, -K * n * i.dot(n), TOL, "-k p on the 45 degree normal")
	assert_almost_eq(f_n.x, f_n.y, TOL, "up and left alike")
	assert_lt(f_n.y, -0.25, "upward, though the hand pushed sideways")
	assert_lt(i.y, 0.0, "it even lifts the relaxed hand")


func test_pointing_away_from_a_wall_in_contact_pulls_only_under_the_paper_sum() -> void:
	# The issue's measurement: about |i| = 0.47 away from the wall on the right, k = 2.
	var away: Vector2 = Vector2(-0.047, 0.0)
	_use(HapticMovementFacts.ContactModel.PAPER_SUM, false)
	_settle(away, _contacts([Vector2.LEFT]))
	var i: Vector2 = door.get_input_vector()
	assert_almost_eq(i.length(), 0.47, 0.05, "the pull draws the relaxed hand in a little")
	var pull: Vector2 = _normal_force()
	assert_almost_eq(pull, Vector2(-K * i.x, 0.0), TOL, "paper_sum: k |i| into the wall")
	assert_gt(pull.x, 0.8)
	_use(HapticMovementFacts.ContactModel.PER_CONTACT, false)
	_settle(away, _contacts([Vector2.LEFT]), 5)
	assert_almost_eq(door.get_forces().total, Vector2.ZERO, TOL, "per_contact: nothing")


func test_one_physics_frame_of_contact_while_pointing_away_through_the_filter() -> void:
	# The wall touches for one physics frame while the hand points away, then is gone: the
	# filtered output over that frame and the filter's tail.
	var into_wall: Dictionary = {"paper_sum": 0.0, "per_contact": 0.0}
	for model: String in into_wall:
		_use(HapticsValue.choice_value(HapticMovementFacts.ContactModel, model), true)
		_settle(Vector2(-0.047, 0.0), HapticFrame.new())
		var most: float = 0.0
		for tick: int in TICKS_PER_FRAME + 200:
			var frame: HapticFrame = (
				_contacts([Vector2.LEFT]) if tick < TICKS_PER_FRAME else HapticFrame.new()
			)
			assert_true(HapticsTestKit.run(door, 1, frame))
			most = maxf(most, door.get_forces().total.x)
		into_wall[model] = most
	assert_gt(into_wall["paper_sum"], 0.3, "the paper's model pulls the hand into the wall")
	assert_almost_eq(into_wall["per_contact"], 0.0, 1e-6, "the per-contact model does not")
