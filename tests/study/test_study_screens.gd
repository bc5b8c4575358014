extends TestSuite
## The study's screens on their own: the start screen checks its fields before it lets a
## session start, the rating screen needs all six answers and works from the keyboard, the
## final screen maps the methods back to conditions, the researcher's consent text replaces
## the shipped one, and the screens wait for a person unless a driver takes part.

const Support := preload("res://tests/study/study_test_support.gd")
const START_SCENE: PackedScene = preload("res://game/study/screens/start_screen.tscn")
const RATING_SCENE: PackedScene = preload("res://game/study/screens/rating_screen.tscn")
const FINAL_SCENE: PackedScene = preload("res://game/study/screens/final_screen.tscn")
const STUDY_SCENE: PackedScene = preload("res://game/study/session/study.tscn")


func test_the_start_screen_checks_its_fields() -> void:
	var screen: StartScreen = add_child_autofree(START_SCENE.instantiate()) as StartScreen
	var requests: Array[String] = []
	screen.start_requested.connect(
		func(id: String, _demographics: Dictionary, _options: Dictionary) -> void:
			requests.append(id)
	)
	screen.start_button.pressed.emit()
	assert_has(screen.problem_label.text, "Enter a participant ID")
	screen.id_edit.text = "P 1"
	screen.start_button.pressed.emit()
	assert_has(screen.problem_label.text, "not a valid participant ID")
	screen.id_edit.text = "P01"
	screen.set_demographic("age_band", "60+")
	screen.start_button.pressed.emit()
	assert_has(
		screen.problem_label.text, "gender, handedness, hand on the device, gaming experience"
	)
	for key: String in ["gender", "handedness", "hand_used", "gaming_experience"]:
		assert_true(screen.set_demographic(key, StudyFormat.demographic_values(key)[0]))
	assert_false(screen.set_demographic("gender", "robot"), "only the format's values")
	screen.start_button.pressed.emit()
	assert_has(screen.problem_label.text, "consent")
	assert_true(requests.is_empty(), "nothing started yet")
	screen.consent_check.button_pressed = true
	screen.start_button.pressed.emit()
	assert_eq(requests, ["P01"] as Array[String])
	assert_false(screen.problem_label.visible)
	assert_eq(screen.get_demographics()["age_band"], "60+")


func test_the_researcher_options_round_trip() -> void:
	var screen: StartScreen = add_child_autofree(START_SCENE.instantiate()) as StartScreen
	screen.set_options("latin_square", "frame", 3)
	assert_eq(
		screen.get_options(),
		{
			"counterbalancing": "latin_square",
			"constraint_update": "frame",
			"trials_per_condition": 3
		}
	)


func test_ratings_need_all_six_answers() -> void:
	var screen: RatingScreen = add_child_autofree(RATING_SCENE.instantiate()) as RatingScreen
	var submitted: Array[Dictionary] = []
	screen.submitted.connect(func(ratings: Dictionary) -> void: submitted.append(ratings))
	screen.setup("Method 2 of 3")
	assert_eq(screen.heading.text, "Method 2 of 3")
	assert_true(screen.submit_button.disabled)
	for i: int in StudyFormat.criteria.size():
		screen.set_rating(StudyFormat.criteria[i], i + 3)
		assert_eq(screen.submit_button.disabled, i < 5, "enabled only with all six")
	screen.set_rating("realism", 10)
	screen.submit_button.pressed.emit()
	assert_eq(submitted.size(), 1)
	assert_eq(
		submitted[0],
		{
			"realism": 10,
			"ease": 4,
			"aptness": 5,
			"intuitiveness": 6,
			"enthusiasm": 7,
			"partiality": 8,
		}
	)


func test_ratings_work_from_the_keyboard() -> void:
	var screen: RatingScreen = add_child_autofree(RATING_SCENE.instantiate()) as RatingScreen
	await wait_process_frames(2)
	var first: Button = screen.buttons["realism"][0]
	assert_true(first.has_focus(), "the first number has the focus")
	_press(&"ui_right")
	var second: Button = screen.buttons["realism"][1]
	assert_true(second.has_focus(), "the right arrow moves to 2")
	_press(&"ui_accept")
	assert_eq(screen.get_ratings(), {"realism": 2}, "Enter picks it")
	_press(&"ui_down")
	var below: Button = screen.buttons["ease"][1]
	assert_true(below.has_focus(), "the down arrow moves to the next criterion")


func test_favourites_map_back_to_conditions() -> void:
	var screen: FinalScreen = add_child_autofree(FINAL_SCENE.instantiate()) as FinalScreen
	var answers: Array = []
	screen.submitted.connect(
		func(favourite: PackedStringArray, text: String) -> void: answers.append([favourite, text])
	)
	screen.setup(PackedStringArray(["constraint", "none", "movement"]))
	await wait_process_frames(1)
	screen.set_favourite(PackedInt32Array([0, 2]))
	screen.text_edit.text = "  felt the walls  "
	screen.submit_button.pressed.emit()
	assert_eq(answers[0][0], PackedStringArray(["constraint", "movement"]), "several")
	assert_eq(answers[0][1], "felt the walls")
	screen.set_favourite(PackedInt32Array())
	screen.submit_button.pressed.emit()
	assert_eq(answers[1][0], PackedStringArray(), "none is a valid answer")


func test_the_researchers_consent_text_replaces_the_shipped_one() -> void:
	var root: String = Support.fresh_root("consent")
	var file: FileAccess = FileAccess.open(root.path_join("consent.txt"), FileAccess.WRITE)
	file.store_string("Our lab's consent text.")
	file.close()
	assert_eq(_consent_shown(root), "Our lab's consent text.")
	DirAccess.remove_absolute(root.path_join("consent.txt"))
	assert_has(_consent_shown(root), "Information and consent", "else the shipped text")
	await wait_process_frames(2)
	Support.remove_tree(root)


func test_a_person_takes_part_unless_a_driver_says_otherwise() -> void:
	var root: String = Support.fresh_root("person")
	var study: StudyRunner = STUDY_SCENE.instantiate() as StudyRunner
	study.study_root = root
	add_child_autofree(study)
	var person: StudyParticipant = study.participant
	if not assert_not_null(person, "the runner has a participant"):
		return
	assert_eq(person.get_script(), StudyParticipant as Script, "the product's own: a person")
	assert_false(person.steers_hand(), "a person moves the device, the mouse or the keys")
	await wait_process_frames(5)
	assert_eq(study.phase, StudySession.Phase.START, "nothing is pressed for them")
	assert_true(study.get_screen() is StartScreen)
	study.queue_free()
	await wait_process_frames(2)
	Support.remove_tree(root)


func _consent_shown(root: String) -> String:
	var study: StudyRunner = STUDY_SCENE.instantiate() as StudyRunner
	study.study_root = root
	add_child_autofree(study)
	var screen: StartScreen = study.get_screen() as StartScreen
	var text: Label = screen.get_node(^"%ConsentText") as Label
	var shown: String = text.text
	study.queue_free()
	return shown


func _press(action: StringName) -> void:
	var event: InputEventAction = InputEventAction.new()
	event.action = action
	event.pressed = true
	get_viewport().push_input(event)
	var release: InputEventAction = InputEventAction.new()
	release.action = action
	release.pressed = false
	get_viewport().push_input(release)
